//! `tw_plan`: the stiffness-feature sequence of a part (issue 13), with
//! accessors for its constraints and the same JSON as `thinwall plan`.

use crate::error::{
    construct, count, cstring, free, guard, json_into, null, string_at, study_failure, tw_status,
};
use crate::options::{options_or_default, tw_options};
use crate::part::{part_ref, tw_part};
use std::ffi::{c_char, CStr, CString};
use thinwall_plan::{Plan, Relation, RuleSet};

/// A plan (opaque). Immutable; safe to share between threads. Strings it
/// returns live as long as it does.
pub struct tw_plan_result {
    plan: std::sync::Arc<Plan>,
    /// Per constraint: the feature machined first (or with the other), the
    /// other, the relation.
    pairs: Vec<(CString, CString, tw_relation)>,
    /// Per constraint: the rule that gave it.
    rules: Vec<CString>,
    /// Per machining feature: id, owner (if any), class, place in the order.
    features: Vec<FeatureEntry>,
}

struct FeatureEntry {
    /// Its type and product adjacency names (`unknown`, `none` unclassified).
    kind: CString,
    adjacency: CString,
    id: CString,
    owner: Option<CString>,
    class: tw_feature_class,
    order: usize,
}

/// What a machining feature of the plan is.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum tw_feature_class {
    /// A step-approach layer `H_RF` tall.
    TW_FEATURE_LARGE = 0,
    /// A step-approach layer `h_RF` tall.
    TW_FEATURE_SMALL = 1,
    /// The rest reachable from up.
    TW_FEATURE_BULK = 2,
    /// Not open to up: another set-up or 5 axes.
    TW_FEATURE_OTHER_SETUP = 3,
    /// A detail's own feature (the material over a chamfer).
    TW_FEATURE_DETAIL = 4,
}

fn feature_entries(plan: &Plan) -> Vec<FeatureEntry> {
    use thinwall_plan::features::FeatureClass;
    plan.machining_features
        .iter()
        .map(|f| FeatureEntry {
            kind: cstring(
                f.classification
                    .as_ref()
                    .map_or("unknown", |c| c.kind.name()),
            ),
            adjacency: cstring(
                f.classification
                    .as_ref()
                    .map_or("none", |c| c.product_adjacency.name()),
            ),
            id: cstring(&f.id),
            owner: f.owner.map(|o| cstring(&o.to_string())),
            class: match f.size_class {
                FeatureClass::Large => tw_feature_class::TW_FEATURE_LARGE,
                FeatureClass::Small => tw_feature_class::TW_FEATURE_SMALL,
                FeatureClass::Bulk => tw_feature_class::TW_FEATURE_BULK,
                FeatureClass::OtherSetup => tw_feature_class::TW_FEATURE_OTHER_SETUP,
                FeatureClass::Detail => tw_feature_class::TW_FEATURE_DETAIL,
            },
            order: plan
                .feature_sequence
                .order
                .iter()
                .position(|o| *o == f.id)
                .unwrap_or(usize::MAX),
        })
        .collect()
}

/// The relation of a sequence constraint.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum tw_relation {
    /// `before` is machined before `after`.
    TW_RELATION_BEFORE = 0,
    /// The two are machined together.
    TW_RELATION_SIMULTANEOUS = 1,
}

/// Plan the part: recognition with `opt` (NULL for the defaults), then the
/// sequence with `rules_toml` (a rule file's text, docs/PLANNING.md; NULL
/// for the shipped rules). A bad rule text is `TW_ERR_INVALID_CONFIG`, its
/// message naming the rule and the line. On success `*out` owns a plan to
/// free with `tw_plan_free`; on failure `*out` is NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_plan(
    part: *const tw_part,
    opt: *const tw_options,
    rules_toml: *const c_char,
    out: *mut *mut tw_plan_result,
) -> tw_status {
    construct("tw_plan", out, || {
        let p = part_ref(part)?;
        let rules = if rules_toml.is_null() {
            RuleSet::default_rules()
        } else {
            let text = CStr::from_ptr(rules_toml).to_str().map_err(|_| {
                (
                    tw_status::TW_ERR_INVALID_ARGUMENT,
                    "rules_toml is not UTF-8".to_string(),
                )
            })?;
            RuleSet::from_toml(text, "rules")
                .map_err(|e| (tw_status::TW_ERR_INVALID_CONFIG, e.to_string()))?
        };
        let o = options_or_default(opt);
        let request = thinwall_study::PlanRequest {
            recognize: o.request.clone(),
            rules,
        };
        let plan = p
            .with_study(o.request.parallel, |study| {
                thinwall_study::plan(study, &request).map(|planned| planned.plan)
            })
            .map_err(study_failure)?;
        let pairs = plan
            .sequence
            .iter()
            .map(|c| {
                let r = match c.relation {
                    Relation::Before => tw_relation::TW_RELATION_BEFORE,
                    Relation::Simultaneous => tw_relation::TW_RELATION_SIMULTANEOUS,
                };
                (
                    cstring(&c.before.to_string()),
                    cstring(&c.after.to_string()),
                    r,
                )
            })
            .collect();
        let rules = plan.sequence.iter().map(|c| cstring(&c.rule)).collect();
        let features = feature_entries(&plan);
        Ok(tw_plan_result {
            plan,
            pairs,
            rules,
            features,
        })
    })
}

/// Free a plan. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_free(plan: *mut tw_plan_result) {
    free(plan)
}

/// The plan as JSON (`thinwall/plan/1`, as the CLI prints it).
/// `*out_json` is a new string to free with `tw_string_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_to_json(
    plan: *const tw_plan_result,
    out_json: *mut *mut c_char,
) -> tw_status {
    json_into("tw_plan_to_json", plan, out_json, |p| {
        thinwall_report::plan::to_json(&p.plan)
    })
}

/// Number of sequence constraints in force (0 for NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_plan_sequence_count(plan: *const tw_plan_result) -> usize {
    count(plan, |p| p.pairs.len())
}

/// Constraint `i`: the feature ids (valid while `plan` lives) and the
/// relation. Any out-pointer may be NULL. `TW_ERR_OUT_OF_RANGE` past the
/// count.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_sequence_pair(
    plan: *const tw_plan_result,
    i: usize,
    before: *mut *const c_char,
    after: *mut *const c_char,
    relation: *mut tw_relation,
) -> tw_status {
    guard("tw_plan_sequence_pair", || {
        if plan.is_null() {
            return Err(null("plan"));
        }
        let p = &*plan;
        let (b, a, r) = p.pairs.get(i).ok_or((
            tw_status::TW_ERR_OUT_OF_RANGE,
            format!("constraint {i} out of range ({} in force)", p.pairs.len()),
        ))?;
        if !before.is_null() {
            *before = b.as_ptr();
        }
        if !after.is_null() {
            *after = a.as_ptr();
        }
        if !relation.is_null() {
            *relation = *r;
        }
        Ok(())
    })
}

/// The rule that gave constraint `i` (valid while `plan` lives); NULL out
/// of range.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_sequence_rule(
    plan: *const tw_plan_result,
    i: usize,
) -> *const c_char {
    string_at(plan, |p| p.rules.get(i))
}

/// Number of machining features of the removal plan (0 for NULL, and 0
/// when the removal could not be decomposed: the JSON says why).
#[no_mangle]
pub unsafe extern "C" fn tw_plan_feature_count(plan: *const tw_plan_result) -> usize {
    count(plan, |p| p.features.len())
}

/// Machining feature `i`: its id and its owner's (NULL when it lies
/// around the part; both valid while `plan` lives), its class, its index
/// in the plan's order (0 first) and its volume in mm³. Any out-pointer
/// may be NULL. `TW_ERR_OUT_OF_RANGE` past the count.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_feature(
    plan: *const tw_plan_result,
    i: usize,
    id: *mut *const c_char,
    owner: *mut *const c_char,
    class: *mut tw_feature_class,
    order_index: *mut usize,
    volume_mm3: *mut f64,
) -> tw_status {
    guard("tw_plan_feature", || {
        if plan.is_null() {
            return Err(null("plan"));
        }
        let p = &*plan;
        let e = p.features.get(i).ok_or((
            tw_status::TW_ERR_OUT_OF_RANGE,
            format!("feature {i} out of range ({} features)", p.features.len()),
        ))?;
        if !id.is_null() {
            *id = e.id.as_ptr();
        }
        if !owner.is_null() {
            *owner = e.owner.as_ref().map_or(std::ptr::null(), |o| o.as_ptr());
        }
        if !class.is_null() {
            *class = e.class;
        }
        if !order_index.is_null() {
            *order_index = e.order;
        }
        if !volume_mm3.is_null() {
            *volume_mm3 = p.plan.machining_features[i].volume_mm3;
        }
        Ok(())
    })
}

/// Machining feature `i`'s solids as STEP text (a new string to free with
/// `tw_string_free`), as `thinwall plan --volumes-dir` writes them.
/// `*not_written` (may be NULL) counts its solids bounded by a cylinder or
/// a cone, not written yet. `TW_ERR_OUT_OF_RANGE` past the count.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_feature_step(
    plan: *const tw_plan_result,
    i: usize,
    out_step: *mut *mut c_char,
    not_written: *mut usize,
) -> tw_status {
    if !out_step.is_null() {
        *out_step = std::ptr::null_mut();
    }
    guard("tw_plan_feature_step", || {
        if plan.is_null() {
            return Err(null("plan"));
        }
        if out_step.is_null() {
            return Err(null("out_step"));
        }
        let p = &*plan;
        let f = p.plan.machining_features.get(i).ok_or((
            tw_status::TW_ERR_OUT_OF_RANGE,
            format!("feature {i} out of range ({} features)", p.features.len()),
        ))?;
        let (text, missing) = thinwall_plan::volumes::feature_step(&p.plan, f);
        if !not_written.is_null() {
            *not_written = missing;
        }
        *out_step = cstring(&text).into_raw();
        Ok(())
    })
}

/// Machining feature `i`'s type (`pocket`, `step`, …, `unknown`) as
/// `thinwall-classify` gives it in the plan's order; NULL out of range.
/// Valid while `plan` lives.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_feature_type(
    plan: *const tw_plan_result,
    i: usize,
) -> *const c_char {
    string_at(plan, |p| p.features.get(i).map(|e| &e.kind))
}

/// Machining feature `i`'s product adjacency (`none`, `side`, `bottom`,
/// `side_and_bottom`); NULL out of range. Valid while `plan` lives.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_feature_adjacency(
    plan: *const tw_plan_result,
    i: usize,
) -> *const c_char {
    string_at(plan, |p| p.features.get(i).map(|e| &e.adjacency))
}
