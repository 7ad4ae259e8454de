//! `tw_classification`: the dedicated classification of machining-feature
//! volumes against a part, with a removal sequence.

use crate::error::{
    construct, count, cstring, free, json_into, null, string_at, study_failure, tw_status,
};
use crate::options::{options_or_default, tw_options};
use crate::part::{part_ref, tw_part};
use std::ffi::{c_char, CString};
use thinwall_report::ClassificationReport;

/// The classification of some volumes (opaque). Immutable; safe to share
/// between threads. Strings it returns live as long as it does.
pub struct tw_classification {
    report: ClassificationReport,
    types: Vec<CString>,
    adjacency: Vec<CString>,
}

/// Classify `n_volumes` volumes (each a part read from its own STEP file)
/// against `part`. `before` holds `n_before` pairs `(a, b)` as `2·n_before`
/// indices: volume `a` is removed before volume `b`. `opt` (may be NULL)
/// gives the up direction. On success `*out` owns a result to free with
/// `tw_classification_free`; on failure `*out` is NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_classify(
    part: *const tw_part,
    volumes: *const *const tw_part,
    n_volumes: usize,
    before: *const usize,
    n_before: usize,
    opt: *const tw_options,
    out: *mut *mut tw_classification,
) -> tw_status {
    construct("tw_classify", out, || {
        let p = part_ref(part)?;
        if volumes.is_null() && n_volumes > 0 {
            return Err(null("volumes"));
        }
        if before.is_null() && n_before > 0 {
            return Err(null("before"));
        }
        let vols: Vec<thinwall_classify::Volume> = (0..n_volumes)
            .map(|i| {
                let v = *volumes.add(i);
                if v.is_null() {
                    return Err(null(&format!("volumes[{i}]")));
                }
                Ok(thinwall_study::volume_of(&(&*v).loaded))
            })
            .collect::<Result<_, _>>()?;
        let pairs: Vec<(usize, usize)> = (0..n_before)
            .map(|k| (*before.add(2 * k), *before.add(2 * k + 1)))
            .collect();
        let o = options_or_default(opt);
        let request = thinwall_study::ClassifyRequest {
            setup: o.request.setup.clone(),
            volumes: vols,
            before: pairs,
        };
        let report = p
            .with_study(o.request.parallel, |study| {
                thinwall_study::classify(study, request).map(|r| r.report)
            })
            .map_err(study_failure)?;
        let types = report
            .volumes
            .iter()
            .map(|c| cstring(c.kind.name()))
            .collect();
        let adjacency = report
            .volumes
            .iter()
            .map(|c| cstring(c.product_adjacency.name()))
            .collect();
        Ok(tw_classification {
            report,
            types,
            adjacency,
        })
    })
}

/// Number of volumes classified (0 for NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_classification_count(res: *const tw_classification) -> usize {
    count(res, |r| r.types.len())
}

/// Type of volume `i` ("pocket", "passage", "blind_slot", "through_slot",
/// "corner_notch", "step", "face", "hole", "free_pocket", "free_passage",
/// "free_step", "unknown"); NULL when out of range.
#[no_mangle]
pub unsafe extern "C" fn tw_classification_type(
    res: *const tw_classification,
    i: usize,
) -> *const c_char {
    string_at(res, |r| r.types.get(i))
}

/// Product adjacency of volume `i` ("none", "side", "bottom",
/// "side_and_bottom"); NULL when out of range.
#[no_mangle]
pub unsafe extern "C" fn tw_classification_product_adjacency(
    res: *const tw_classification,
    i: usize,
) -> *const c_char {
    string_at(res, |r| r.adjacency.get(i))
}

/// The classification as JSON (as `thinwall classify --format json` prints
/// it); a new string to free with `tw_string_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_classification_to_json(
    res: *const tw_classification,
    out_json: *mut *mut c_char,
) -> tw_status {
    json_into("tw_classification_to_json", res, out_json, |r| {
        r.report.to_json()
    })
}

/// Free a classification. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_classification_free(res: *mut tw_classification) {
    free(res)
}
