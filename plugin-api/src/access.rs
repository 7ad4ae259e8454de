//! `tw_access`: how much of each face a tool and its holder reach with
//! material in the way, and which planar faces can be flank milled (their
//! G-zones, issue 16), with per-face accessors and the same JSON as
//! `thinwall access`.

use crate::error::{construct, count, free, guard, json_into, null, study_failure, tw_status};
use crate::options::{options_or_default, tw_options};
use crate::part::{part_ref, tw_part};
use std::ffi::c_char;
use thinwall_access::reach::Tool;
use thinwall_access::Nature;
use thinwall_report::access::AccessReport;
use thinwall_study::AccessRequest;

/// An accessibility result (opaque). Immutable; safe to share between
/// threads.
pub struct tw_access_result {
    report: AccessReport,
}

/// A planar face's nature for flank milling.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum tw_face_nature {
    /// Every edge rises: no way in along its plane.
    TW_FACE_CLOSED = 0,
    /// No edge rises.
    TW_FACE_OPEN = 1,
    TW_FACE_SEMI_OPEN = 2,
}

/// Flank milling of every planar face of `part` in the set-up of `opt`
/// (NULL for the defaults: up +Z): a tool of `tool_diameter` mm (0 for the
/// default Ø12; obstacles count that far above a face), a face advisable
/// when at least `threshold` of it is reached (0 for the default 0.95). A
/// negative diameter or a threshold above 1 is `TW_ERR_INVALID_ARGUMENT`.
/// On success `*out` owns a result to free with `tw_access_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_access(
    part: *const tw_part,
    opt: *const tw_options,
    tool_diameter: f64,
    threshold: f64,
    out: *mut *mut tw_access_result,
) -> tw_status {
    construct("tw_access", out, || {
        let p = part_ref(part)?;
        let o = options_or_default(opt);
        let mut request = AccessRequest::new(o.request.setup.clone());
        // 0 asks for the default of either value.
        if tool_diameter != 0.0 {
            request.tool = Tool::new(tool_diameter);
        }
        if threshold != 0.0 {
            request.threshold = threshold;
        }
        request.walls = o.request.clone();
        request.walls.reach_tool = None;
        request.walls.allow_open = true;
        let report = p
            .with_study(o.request.parallel, |study| {
                thinwall_study::access(study, &request).map(|r| r.report)
            })
            .map_err(study_failure)?;
        Ok(tw_access_result { report })
    })
}

/// Free an accessibility result. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_access_free(result: *mut tw_access_result) {
    free(result)
}

/// The result as JSON (`thinwall/access/1`, as the CLI prints it).
/// `*out_json` is a new string to free with `tw_string_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_access_to_json(
    result: *const tw_access_result,
    out_json: *mut *mut c_char,
) -> tw_status {
    json_into("tw_access_to_json", result, out_json, |r| {
        r.report.to_json()
    })
}

/// Number of planar faces judged (0 for NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_access_face_count(result: *const tw_access_result) -> usize {
    count(result, |r| r.report.planar_faces.len())
}

/// Planar face `i`: its STEP entity id, nature, area (mm²), the fraction
/// of it flank milling reaches (0–1) and whether that makes it advisable.
/// Any out-pointer may be NULL. `TW_ERR_OUT_OF_RANGE` past the count.
#[no_mangle]
pub unsafe extern "C" fn tw_access_face(
    result: *const tw_access_result,
    i: usize,
    step_id: *mut u64,
    nature: *mut tw_face_nature,
    area_mm2: *mut f64,
    reached: *mut f64,
    advisable: *mut bool,
) -> tw_status {
    guard("tw_access_face", || {
        if result.is_null() {
            return Err(null("result"));
        }
        let faces = &(*result).report.planar_faces;
        let f = faces.get(i).ok_or((
            tw_status::TW_ERR_OUT_OF_RANGE,
            format!("face {i} out of range ({} faces)", faces.len()),
        ))?;
        if !step_id.is_null() {
            *step_id = f.face;
        }
        if !nature.is_null() {
            *nature = match f.nature {
                Nature::Closed => tw_face_nature::TW_FACE_CLOSED,
                Nature::Open => tw_face_nature::TW_FACE_OPEN,
                Nature::SemiOpen => tw_face_nature::TW_FACE_SEMI_OPEN,
            };
        }
        if !area_mm2.is_null() {
            *area_mm2 = f.area_mm2;
        }
        if !reached.is_null() {
            *reached = f.visibility;
        }
        if !advisable.is_null() {
            *advisable = f.advisable;
        }
        Ok(())
    })
}

/// Number of faces whose reach was judged: every face of the part (0 for
/// NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_access_reach_count(result: *const tw_access_result) -> usize {
    count(result, |r| r.report.faces.len())
}

/// Face `i`'s reach with the tool (its diameter as given to `tw_access`,
/// cutting length three diameters, holder two) on the set-up's axis, or on
/// five axes the best axis: its STEP entity id, the fraction reached
/// (0–1), the area not reached (mm²) and, for a floor, the largest tool of
/// those proportions reaching it whole (mm; NaN when not a floor or none
/// does). Any out-pointer may be NULL. `TW_ERR_OUT_OF_RANGE` past the count.
#[no_mangle]
pub unsafe extern "C" fn tw_access_reach(
    result: *const tw_access_result,
    i: usize,
    step_id: *mut u64,
    fraction: *mut f64,
    unreachable_mm2: *mut f64,
    largest_tool_mm: *mut f64,
) -> tw_status {
    guard("tw_access_reach", || {
        if result.is_null() {
            return Err(null("result"));
        }
        let faces = &(*result).report.faces;
        let f = faces.get(i).ok_or((
            tw_status::TW_ERR_OUT_OF_RANGE,
            format!("face {i} out of range ({} faces)", faces.len()),
        ))?;
        if !step_id.is_null() {
            *step_id = f.face;
        }
        if !fraction.is_null() {
            *fraction = f.fraction;
        }
        if !unreachable_mm2.is_null() {
            *unreachable_mm2 = f.unreachable_mm2;
        }
        if !largest_tool_mm.is_null() {
            *largest_tool_mm = f.largest_tool_mm.unwrap_or(f64::NAN);
        }
        Ok(())
    })
}
