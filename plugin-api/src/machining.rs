//! A recognition result's machining features, with typed accessors: ids,
//! kinds, faces and sizes, a pocket's corner radius, floor fillet and
//! draft, and a hole's stages (entry, bores, exit, tip). The same values
//! as the JSON's `machining_features`.

use crate::error::{count, guard, null, string_at, tw_status};
use crate::result::tw_result;
use std::ffi::c_char;
use thinwall_machining::{HoleEnd, HoleTip, MachiningFeature};

/// How one end of a hole is finished.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum tw_hole_end {
    /// A plain edge.
    TW_HOLE_END_NONE = 0,
    /// A cone seating a screw head (angle, diameter on the face).
    TW_HOLE_END_COUNTERSINK = 1,
    /// A cone breaking the edge (angle, diameter on the face).
    TW_HOLE_END_CHAMFER = 2,
    /// A rounded edge (radius).
    TW_HOLE_END_BLEND = 3,
}

/// How a hole ends.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum tw_hole_tip {
    TW_HOLE_TIP_THROUGH = 0,
    TW_HOLE_TIP_FLAT = 1,
    /// A drill's cone (its included angle).
    TW_HOLE_TIP_DRILL_POINT = 2,
}

/// Machining feature `i` of a result, or the error a caller gets.
unsafe fn feature<'r>(
    res: *const tw_result,
    i: usize,
) -> Result<&'r MachiningFeature, (tw_status, String)> {
    if res.is_null() {
        return Err(null("res"));
    }
    (&*res).report().machining_features.get(i).ok_or((
        tw_status::TW_ERR_OUT_OF_RANGE,
        format!("machining feature {i} out of range"),
    ))
}

/// Write `v` where `ptr` points, unless it is NULL.
unsafe fn put<T>(ptr: *mut T, v: T) {
    if !ptr.is_null() {
        *ptr = v;
    }
}

/// Number of machining features (0 for NULL).
#[no_mangle]
pub unsafe extern "C" fn tw_result_machining_count(res: *const tw_result) -> usize {
    count(res, |r| r.report().machining_features.len())
}

/// Id of machining feature `i` ("M3"); NULL when out of range. Valid while
/// `res` lives.
#[no_mangle]
pub unsafe extern "C" fn tw_result_machining_id(res: *const tw_result, i: usize) -> *const c_char {
    string_at(res, |r| r.machining_ids().get(i))
}

/// Kind of machining feature `i` ("hole", "pocket", "slot", "step",
/// "passage", "chamfer", "fillet", "boss", "face"); NULL when out of range.
/// Valid while `res` lives.
#[no_mangle]
pub unsafe extern "C" fn tw_result_machining_kind(
    res: *const tw_result,
    i: usize,
) -> *const c_char {
    string_at(res, |r| r.machining_kinds().get(i))
}

/// Sizes of machining feature `i`, mm: depth along its direction, length
/// and width across it, and the largest tool that fits it (NaN when there
/// is no floor to measure). Any out-pointer may be NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_result_machining_sizes(
    res: *const tw_result,
    i: usize,
    depth: *mut f64,
    length: *mut f64,
    width: *mut f64,
    largest_tool: *mut f64,
) -> tw_status {
    guard("tw_result_machining_sizes", || {
        let m = feature(res, i)?;
        put(depth, m.depth);
        put(length, m.length);
        put(width, m.width);
        put(largest_tool, m.largest_tool_diameter.unwrap_or(f64::NAN));
        Ok(())
    })
}

/// A pocket's, slot's, step's or passage's corner radius and floor fillet
/// (mm) and wall draft (degrees); NaN for what it does not have. Any
/// out-pointer may be NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_result_machining_blends(
    res: *const tw_result,
    i: usize,
    corner_radius: *mut f64,
    floor_fillet: *mut f64,
    wall_draft_deg: *mut f64,
) -> tw_status {
    guard("tw_result_machining_blends", || {
        let m = feature(res, i)?;
        put(corner_radius, m.corner_radius.unwrap_or(f64::NAN));
        put(floor_fillet, m.floor_fillet.unwrap_or(f64::NAN));
        put(wall_draft_deg, m.wall_draft_deg.unwrap_or(f64::NAN));
        Ok(())
    })
}

/// An end as its kind, angle (degrees; NaN for a blend or none) and size
/// (mm: a cone's diameter on the face, a blend's radius; NaN for none).
fn end(e: Option<&HoleEnd>) -> (tw_hole_end, f64, f64) {
    match e {
        None => (tw_hole_end::TW_HOLE_END_NONE, f64::NAN, f64::NAN),
        Some(HoleEnd::Countersink {
            angle_deg,
            diameter,
        }) => (tw_hole_end::TW_HOLE_END_COUNTERSINK, *angle_deg, *diameter),
        Some(HoleEnd::Chamfer {
            angle_deg,
            diameter,
        }) => (tw_hole_end::TW_HOLE_END_CHAMFER, *angle_deg, *diameter),
        Some(HoleEnd::Blend { radius }) => (tw_hole_end::TW_HOLE_END_BLEND, f64::NAN, *radius),
    }
}

/// A hole's stages: its entry and exit (kind, included angle in degrees,
/// size in mm: a cone's diameter on the face or a blend's radius; NaN
/// where not applicable), how many bores it has (read each with
/// `tw_result_machining_bore`), and its tip (with a drill point's included
/// angle, else NaN). `TW_ERR_NOT_APPLICABLE` for a feature that is not a
/// hole. Any out-pointer may be NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_result_machining_hole(
    res: *const tw_result,
    i: usize,
    entry: *mut tw_hole_end,
    entry_angle_deg: *mut f64,
    entry_size: *mut f64,
    exit: *mut tw_hole_end,
    exit_angle_deg: *mut f64,
    exit_size: *mut f64,
    bores: *mut usize,
    tip: *mut tw_hole_tip,
    tip_angle_deg: *mut f64,
) -> tw_status {
    guard("tw_result_machining_hole", || {
        let m = feature(res, i)?;
        let h = m.hole.as_ref().ok_or((
            tw_status::TW_ERR_NOT_APPLICABLE,
            format!("{} is a {}, not a hole", m.id, m.kind),
        ))?;
        let (k, a, s) = end(h.entry.as_ref());
        put(entry, k);
        put(entry_angle_deg, a);
        put(entry_size, s);
        let (k, a, s) = end(h.exit.as_ref());
        put(exit, k);
        put(exit_angle_deg, a);
        put(exit_size, s);
        put(bores, h.bores.len());
        let (t, angle) = match h.tip {
            HoleTip::Through => (tw_hole_tip::TW_HOLE_TIP_THROUGH, f64::NAN),
            HoleTip::Flat => (tw_hole_tip::TW_HOLE_TIP_FLAT, f64::NAN),
            HoleTip::DrillPoint { angle_deg } => (tw_hole_tip::TW_HOLE_TIP_DRILL_POINT, angle_deg),
        };
        put(tip, t);
        put(tip_angle_deg, angle);
        Ok(())
    })
}

/// Bore `k` of hole `i`, from the entry down: its diameter and depth along
/// the axis, mm. `TW_ERR_NOT_APPLICABLE` for a feature that is not a hole,
/// `TW_ERR_OUT_OF_RANGE` past its last bore. Any out-pointer may be NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_result_machining_bore(
    res: *const tw_result,
    i: usize,
    k: usize,
    diameter: *mut f64,
    depth: *mut f64,
) -> tw_status {
    guard("tw_result_machining_bore", || {
        let m = feature(res, i)?;
        let h = m.hole.as_ref().ok_or((
            tw_status::TW_ERR_NOT_APPLICABLE,
            format!("{} is a {}, not a hole", m.id, m.kind),
        ))?;
        let b = h.bores.get(k).ok_or((
            tw_status::TW_ERR_OUT_OF_RANGE,
            format!("{} has {} bores, not {}", m.id, h.bores.len(), k + 1),
        ))?;
        put(diameter, b.diameter);
        put(depth, b.depth);
        Ok(())
    })
}
