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
        let o = options_or_default(opt);
        let request = thinwall_study::PlanRequest::new(o.request.clone(), rules_of(rules_toml)?);
        planned(part, opt, &request)
    })
}

/// Plan the part over several set-ups in turn, as `thinwall plan --up A
/// --up B …`: `ups` holds `n_ups` directions (x, y, z each, in the part's
/// coordinates), each set-up planning what those before it left; `n_ups`
/// 0 (`ups` may then be NULL) proposes the set-ups, as `thinwall plan`
/// without `--up`. `opt` gives the recognition settings (its up is not
/// used; no placement), `rules_toml` as `tw_plan`. `*out` reads the first
/// set-up; `tw_plan_setup_count` and `tw_plan_setup_at` give the others,
/// and its JSON holds them all (`then`, `residue`, `proposal`). A zero
/// direction is `TW_ERR_INVALID_ARGUMENT`. Free with `tw_plan_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_setups(
    part: *const tw_part,
    opt: *const tw_options,
    ups: *const f64,
    n_ups: usize,
    rules_toml: *const c_char,
    out: *mut *mut tw_plan_result,
) -> tw_status {
    construct("tw_plan_setups", out, || {
        if n_ups > 0 && ups.is_null() {
            return Err(null("ups"));
        }
        let o = options_or_default(opt);
        let mut recognize = o.request.clone();
        recognize.setup.placement = None;
        let dirs: Vec<[f64; 3]> = if n_ups == 0 {
            Vec::new()
        } else {
            std::slice::from_raw_parts(ups, 3 * n_ups)
                .chunks(3)
                .map(|c| [c[0], c[1], c[2]])
                .collect()
        };
        if let Some(first) = dirs.first() {
            recognize.setup.up = *first;
        }
        let mut request = thinwall_study::PlanRequest::new(recognize, rules_of(rules_toml)?);
        request.propose = dirs.is_empty();
        request.later_ups = dirs.iter().skip(1).copied().collect();
        planned(part, opt, &request)
    })
}

/// The rules of a rule file's text, or the shipped ones for NULL.
unsafe fn rules_of(rules_toml: *const c_char) -> Result<RuleSet, crate::error::Failure> {
    if rules_toml.is_null() {
        return Ok(RuleSet::default_rules());
    }
    let text = CStr::from_ptr(rules_toml).to_str().map_err(|_| {
        (
            tw_status::TW_ERR_INVALID_ARGUMENT,
            "rules_toml is not UTF-8".to_string(),
        )
    })?;
    RuleSet::from_toml(text, "rules").map_err(|e| (tw_status::TW_ERR_INVALID_CONFIG, e.to_string()))
}

/// The plan of `request` on `part` as a result.
unsafe fn planned(
    part: *const tw_part,
    opt: *const tw_options,
    request: &thinwall_study::PlanRequest,
) -> Result<tw_plan_result, crate::error::Failure> {
    let p = part_ref(part)?;
    let o = options_or_default(opt);
    let plan = p
        .with_study(o.request.parallel, |study| {
            thinwall_study::plan(study, request).map(|planned| planned.plan)
        })
        .map_err(study_failure)?;
    Ok(result_of(plan))
}

/// A result over `plan` (its accessors read this set-up's).
fn result_of(plan: std::sync::Arc<Plan>) -> tw_plan_result {
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
    tw_plan_result {
        plan,
        pairs,
        rules,
        features,
    }
}

/// The number of set-ups of a plan (1 for a plan of one set-up).
#[no_mangle]
pub unsafe extern "C" fn tw_plan_setup_count(
    plan: *const tw_plan_result,
    count: *mut usize,
) -> tw_status {
    guard("tw_plan_setup_count", || {
        if plan.is_null() {
            return Err(null("plan"));
        }
        if count.is_null() {
            return Err(null("count"));
        }
        let p = &*plan;
        *count = 1 + p.plan.then.len();
        Ok(())
    })
}

/// Set-up `index` (0 the first) of a plan, as a plan of its own: its up,
/// constraints, machining features and JSON that set-up's alone.
/// `TW_ERR_OUT_OF_RANGE` past the last. Free with `tw_plan_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_setup_at(
    plan: *const tw_plan_result,
    index: usize,
    out: *mut *mut tw_plan_result,
) -> tw_status {
    construct("tw_plan_setup_at", out, || {
        if plan.is_null() {
            return Err(null("plan"));
        }
        let first = &(*plan).plan;
        let count = 1 + first.then.len();
        let mut one = match index {
            0 => Plan::clone(first),
            i if i < count => first.then[i - 1].clone(),
            _ => {
                return Err((
                    tw_status::TW_ERR_OUT_OF_RANGE,
                    format!("set-up {index} of {count}"),
                ))
            }
        };
        one.then = Vec::new();
        one.residue = None;
        one.proposal = None;
        Ok(result_of(std::sync::Arc::new(one)))
    })
}

/// Free a plan. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_plan_free(plan: *mut tw_plan_result) {
    free(plan)
}

/// The plan as JSON (`thinwall/plan/2`, as the CLI prints it).
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
