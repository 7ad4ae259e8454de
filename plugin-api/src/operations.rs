//! `tw_operations`: the operations of a set-up (issue 17): layers, cutter
//! fields, tools with rest areas and regions, floors' finishing and holes
//! drilled, in order, with per-operation accessors and the same JSON as
//! `thinwall operations`.

use crate::error::{
    construct, count, cstring, guard, json_into, null, string_at, study_failure, tw_status,
};
use crate::options::{options_or_default, tw_options};
use crate::part::{part_ref, tw_part};
use std::ffi::{c_char, CStr, CString};
use thinwall_ops::operations::Stage;
use thinwall_ops::ToolLibrary;
use thinwall_report::operations::OperationsReport;
use thinwall_study::OperationsRequest;

/// A set-up's operations (opaque). Immutable; safe to share between
/// threads.
pub struct tw_operations_result {
    report: OperationsReport,
    tools: Vec<CString>,
}

/// What an operation does.
#[repr(C)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum tw_stage {
    /// A field's first (largest) end mill.
    TW_STAGE_ROUGH = 0,
    /// A smaller end mill in what larger ones left (rest machining).
    TW_STAGE_SEMI_FINISH = 1,
    /// A floor's finishing layer.
    TW_STAGE_FINISH = 2,
    /// Holes with a drill.
    TW_STAGE_DRILL = 3,
    /// Along the walls: a tool's boundary region at finishing conditions.
    TW_STAGE_FINISH_WALLS = 4,
    /// A pocket's walls, corners and floor fillet contoured by a tool
    /// chosen by its corner radius and floor fillet.
    TW_STAGE_FINISH_RADII = 5,
}

/// The library of `tools_toml` (UTF-8 TOML text as the `--tools` file), or
/// the shipped one for NULL.
unsafe fn library(tools_toml: *const c_char) -> Result<ToolLibrary, (tw_status, String)> {
    if tools_toml.is_null() {
        return Ok(ToolLibrary::default_tools());
    }
    let text = CStr::from_ptr(tools_toml).to_str().map_err(|e| {
        (
            tw_status::TW_ERR_INVALID_ARGUMENT,
            format!("tools_toml is not UTF-8: {e}"),
        )
    })?;
    ToolLibrary::from_toml(text, "tools_toml")
        .map_err(|e| study_failure(thinwall_study::StudyError::from(e)))
}

/// Plan the operations of `part` in the set-up of `opt` (NULL for the
/// defaults: up +Z) with the tool library `tools_toml` (TOML text as
/// `thinwall operations --tools` reads; NULL for the shipped library) and
/// an axial depth of cut `axial_depth` mm between levels (0 for the largest
/// end mill's). A bad library is `TW_ERR_INVALID_CONFIG` with the line; a
/// negative depth `TW_ERR_INVALID_ARGUMENT`; a face the removal cannot take
/// yet `TW_ERR_UNSUPPORTED`. A part with nothing to remove gives an empty
/// list. On success `*out` owns a result to free with
/// `tw_operations_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_operations(
    part: *const tw_part,
    opt: *const tw_options,
    tools_toml: *const c_char,
    axial_depth: f64,
    out: *mut *mut tw_operations_result,
) -> tw_status {
    construct("tw_operations", out, || {
        run(part, opt, tools_toml, axial_depth, false)
    })
}

/// As `tw_operations`, then the set-up from the opposite side (up
/// reversed) after it, as `thinwall operations --both-sides`: it cuts what
/// the first left under the part (the far side of a web pocketed from both
/// sides), what the first reached gone. `*out` reads the first set-up (its
/// JSON has both, the second under `second`); `tw_operations_second` gives
/// the second. Free with `tw_operations_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_operations_both_sides(
    part: *const tw_part,
    opt: *const tw_options,
    tools_toml: *const c_char,
    axial_depth: f64,
    out: *mut *mut tw_operations_result,
) -> tw_status {
    construct("tw_operations_both_sides", out, || {
        run(part, opt, tools_toml, axial_depth, true)
    })
}

/// The operations of `part`, one set-up or both sides.
unsafe fn run(
    part: *const tw_part,
    opt: *const tw_options,
    tools_toml: *const c_char,
    axial_depth: f64,
    both_sides: bool,
) -> Result<tw_operations_result, crate::error::Failure> {
    let o = options_or_default(opt);
    let mut request = OperationsRequest::new(o.request.setup.clone());
    request.both_sides = both_sides;
    planned(part, opt, tools_toml, axial_depth, request)
}

/// `request` with the library and depth given, run on `part`.
unsafe fn planned(
    part: *const tw_part,
    opt: *const tw_options,
    tools_toml: *const c_char,
    axial_depth: f64,
    mut request: OperationsRequest,
) -> Result<tw_operations_result, crate::error::Failure> {
    let p = part_ref(part)?;
    let o = options_or_default(opt);
    request.tools = library(tools_toml)?;
    // 0 asks for the largest end mill's depth.
    request.axial_depth = (axial_depth != 0.0).then_some(axial_depth);
    let report = p
        .with_study(o.request.parallel, |study| {
            thinwall_study::operations(study, &request).map(|r| r.report)
        })
        .map_err(study_failure)?;
    Ok(result_of(report))
}

/// Plan `part`'s operations over several set-ups in turn, as `thinwall
/// operations --up A --up B …`: `ups` holds `n_ups` directions (x, y, z
/// each, in the part's coordinates), each set-up cutting what those before
/// it left; `n_ups` 0 (`ups` may then be NULL) proposes the set-ups, as
/// `thinwall operations` without `--up`: the fewest ups that reach stock −
/// part, the most material first. `opt` gives the machine and parallelism
/// (its up is not used; no placement); the library and depth as
/// `tw_operations`. `*out` reads the first set-up;
/// `tw_operations_setup_count` and `tw_operations_setup_at` give the others,
/// `tw_operations_residue` what none reaches. A zero direction is
/// `TW_ERR_INVALID_ARGUMENT`. Free with `tw_operations_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_operations_setups(
    part: *const tw_part,
    opt: *const tw_options,
    ups: *const f64,
    n_ups: usize,
    tools_toml: *const c_char,
    axial_depth: f64,
    out: *mut *mut tw_operations_result,
) -> tw_status {
    construct("tw_operations_setups", out, || {
        if n_ups > 0 && ups.is_null() {
            return Err(null("ups"));
        }
        let o = options_or_default(opt);
        let mut setup = o.request.setup.clone();
        let mut request = if n_ups == 0 {
            let mut r = OperationsRequest::new(setup);
            r.choose_up = true;
            r
        } else {
            let given = std::slice::from_raw_parts(ups, 3 * n_ups);
            let dirs: Vec<[f64; 3]> = given.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
            setup.up = dirs[0];
            let mut r = OperationsRequest::new(setup);
            r.later_ups = dirs[1..].to_vec();
            r
        };
        request.setup.placement = None;
        planned(part, opt, tools_toml, axial_depth, request)
    })
}

/// A result over `report`'s first set-up.
fn result_of(report: OperationsReport) -> tw_operations_result {
    let tools = report
        .setup
        .operations
        .iter()
        .map(|o| cstring(&o.tool))
        .collect();
    tw_operations_result { report, tools }
}

/// The second set-up of a result (from `tw_operations_both_sides` or
/// `tw_operations_setups`), as a result of its own: `tw_operations_setup_at`
/// with index 1. `TW_ERR_NOT_APPLICABLE` for a result of one set-up. Free
/// with `tw_operations_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_operations_second(
    result: *const tw_operations_result,
    out: *mut *mut tw_operations_result,
) -> tw_status {
    construct("tw_operations_second", out, || setup_at(result, 1))
}

/// How many set-ups a result holds (1, or more from
/// `tw_operations_both_sides` and `tw_operations_setups`).
#[no_mangle]
pub unsafe extern "C" fn tw_operations_setup_count(
    result: *const tw_operations_result,
    count: *mut usize,
) -> tw_status {
    guard("tw_operations_setup_count", || {
        if result.is_null() {
            return Err(null("result"));
        }
        if count.is_null() {
            return Err(null("count"));
        }
        *count = 1 + (*result).report.then.len();
        Ok(())
    })
}

/// Set-up `index` (0 the first) of a result, as a result of its own: its
/// up, its operations, its JSON that set-up's report alone.
/// `TW_ERR_OUT_OF_RANGE` past the last. Free with `tw_operations_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_operations_setup_at(
    result: *const tw_operations_result,
    index: usize,
    out: *mut *mut tw_operations_result,
) -> tw_status {
    construct("tw_operations_setup_at", out, || setup_at(result, index))
}

/// Set-up `index` of `result` as a result of its own.
unsafe fn setup_at(
    result: *const tw_operations_result,
    index: usize,
) -> Result<tw_operations_result, crate::error::Failure> {
    if result.is_null() {
        return Err(null("result"));
    }
    let first = &(*result).report;
    let mut report = first.clone();
    report.then = Vec::new();
    report.residue = None;
    report.proposal = None;
    if index == 0 {
        return Ok(result_of(report));
    }
    let later = first.then.get(index - 1).ok_or_else(|| {
        let status = if index == 1 {
            tw_status::TW_ERR_NOT_APPLICABLE
        } else {
            tw_status::TW_ERR_OUT_OF_RANGE
        };
        (
            status,
            format!(
                "this result has {} set-up(s), no set-up {index}",
                1 + first.then.len()
            ),
        )
    })?;
    report.up = later.up;
    report.frame = later.frame;
    report.setup = later.setup.clone();
    Ok(result_of(report))
}

/// What no set-up of the result reaches, mm³ (0 for a result of one
/// set-up, which leaves what it does not reach to another:
/// `tw_operations_volumes`).
#[no_mangle]
pub unsafe extern "C" fn tw_operations_residue(
    result: *const tw_operations_result,
    residue_mm3: *mut f64,
) -> tw_status {
    guard("tw_operations_residue", || {
        if result.is_null() {
            return Err(null("result"));
        }
        if residue_mm3.is_null() {
            return Err(null("residue_mm3"));
        }
        *residue_mm3 = (*result)
            .report
            .residue
            .as_ref()
            .map_or(0.0, |r| r.volume_mm3);
        Ok(())
    })
}

/// The set-up's volumes, mm³: what it leaves to another set-up (material
/// under the part its up does not reach) and what a set-up before it took
/// (0 for a first set-up). Either pointer may be NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_operations_volumes(
    result: *const tw_operations_result,
    out_of_reach_mm3: *mut f64,
    cleared_before_mm3: *mut f64,
) -> tw_status {
    two_figures(
        "tw_operations_volumes",
        result,
        (out_of_reach_mm3, cleared_before_mm3),
        |s| (s.out_of_reach_mm3, s.cleared_before_mm3),
    )
}

/// Two figures of the result's set-up into the out-pointers that are not
/// NULL.
unsafe fn two_figures<T>(
    stage: &'static str,
    result: *const tw_operations_result,
    (a, b): (*mut T, *mut T),
    pick: impl FnOnce(&thinwall_ops::operations::SetupOperations) -> (T, T),
) -> tw_status {
    guard(stage, || {
        if result.is_null() {
            return Err(null("result"));
        }
        let (x, y) = pick(&(*result).report.setup);
        if !a.is_null() {
            *a = x;
        }
        if !b.is_null() {
            *b = y;
        }
        Ok(())
    })
}

/// Free an operations result. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_operations_free(result: *mut tw_operations_result) {
    crate::error::free(result)
}

/// The result as JSON (`thinwall/operations/2`, as the CLI prints it).
/// `*out_json` is a new string to free with `tw_string_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_operations_to_json(
    result: *const tw_operations_result,
    out_json: *mut *mut c_char,
) -> tw_status {
    json_into("tw_operations_to_json", result, out_json, |r| {
        r.report.to_json()
    })
}

/// Number of operations, in their order (0 for NULL or nothing to remove).
#[no_mangle]
pub unsafe extern "C" fn tw_operations_count(result: *const tw_operations_result) -> usize {
    count(result, |r| r.report.setup.operations.len())
}

/// Tool changes of the chosen order and of the plain layer-by-layer one.
/// Any out-pointer may be NULL.
#[no_mangle]
pub unsafe extern "C" fn tw_operations_tool_changes(
    result: *const tw_operations_result,
    changes: *mut usize,
    plain: *mut usize,
) -> tw_status {
    two_figures(
        "tw_operations_tool_changes",
        result,
        (changes, plain),
        |s| (s.tool_changes, s.plain_tool_changes),
    )
}

/// Operation `i` (in order): its stage, tool diameter (mm), z range along
/// up in the removal frame (mm), area (mm²: what it clears, the floor it
/// finishes or its holes' cross-sections), volume (mm³) and estimated time
/// (min). Any out-pointer may be NULL. `TW_ERR_OUT_OF_RANGE` past the
/// count.
#[no_mangle]
pub unsafe extern "C" fn tw_operation(
    result: *const tw_operations_result,
    i: usize,
    stage: *mut tw_stage,
    diameter_mm: *mut f64,
    z_top_mm: *mut f64,
    z_bottom_mm: *mut f64,
    area_mm2: *mut f64,
    volume_mm3: *mut f64,
    time_min: *mut f64,
) -> tw_status {
    guard("tw_operation", || {
        if result.is_null() {
            return Err(null("result"));
        }
        let ops = &(*result).report.setup.operations;
        let o = ops.get(i).ok_or((
            tw_status::TW_ERR_OUT_OF_RANGE,
            format!("operation {i} out of range ({} operations)", ops.len()),
        ))?;
        let put = |p: *mut f64, v: f64| {
            if !p.is_null() {
                *p = v;
            }
        };
        if !stage.is_null() {
            *stage = match o.stage {
                Stage::Rough => tw_stage::TW_STAGE_ROUGH,
                Stage::SemiFinish => tw_stage::TW_STAGE_SEMI_FINISH,
                Stage::Finish => tw_stage::TW_STAGE_FINISH,
                Stage::FinishWalls => tw_stage::TW_STAGE_FINISH_WALLS,
                Stage::Drill => tw_stage::TW_STAGE_DRILL,
                Stage::FinishRadii => tw_stage::TW_STAGE_FINISH_RADII,
            };
        }
        put(diameter_mm, o.diameter_mm);
        put(z_top_mm, o.z_top_mm);
        put(z_bottom_mm, o.z_bottom_mm);
        put(area_mm2, o.area_mm2);
        put(volume_mm3, o.volume_mm3);
        put(time_min, o.time_min);
        Ok(())
    })
}

/// Operation `i`'s tool name from the library (owned by the result), or
/// NULL past the count or for a NULL result.
#[no_mangle]
pub unsafe extern "C" fn tw_operation_tool(
    result: *const tw_operations_result,
    i: usize,
) -> *const c_char {
    string_at(result, |r| r.tools.get(i))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::part::{tw_part_free, tw_part_load_file};

    unsafe fn load(name: &str) -> *mut tw_part {
        let path = format!("{}/../fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
        let c = CString::new(path).unwrap();
        let mut part = std::ptr::null_mut();
        assert_eq!(tw_part_load_file(c.as_ptr(), &mut part), tw_status::TW_OK);
        part
    }

    /// `part`'s operations are refused as unsupported, the message starting
    /// with `code` and naming `what`; the part is freed.
    unsafe fn refused(part: *mut tw_part, code: &str, what: &str) {
        let mut bad = std::ptr::null_mut();
        let st = tw_operations(part, std::ptr::null(), std::ptr::null(), 0.0, &mut bad);
        assert_eq!(st, tw_status::TW_ERR_UNSUPPORTED);
        assert!(bad.is_null());
        let msg = CStr::from_ptr(crate::tw_last_error_message())
            .to_str()
            .unwrap();
        assert!(msg.starts_with(code) && msg.contains(what), "{msg}");
        tw_part_free(part);
    }

    /// The drill plate's operations through the ABI: the drilling
    /// operations and their spots, and the same count and order as the report's JSON; a
    /// turned panel's tilted faces meshed and named in the JSON; a removal
    /// that does not add up `TW_ERR_UNSUPPORTED` naming a face; a tool
    /// file with a negative diameter `TW_ERR_INVALID_CONFIG` with its
    /// line; a negative depth an invalid argument. Out stays NULL on
    /// failure.
    #[test]
    fn operations_through_the_abi_and_their_errors() {
        unsafe {
            let plate = load("ops/drill_plate.step");
            let mut ops = std::ptr::null_mut();
            let st = tw_operations(plate, std::ptr::null(), std::ptr::null(), 0.0, &mut ops);
            assert_eq!(st, tw_status::TW_OK);
            let n = tw_operations_count(ops);
            let mut drills = 0;
            for i in 0..n {
                let mut stage = tw_stage::TW_STAGE_ROUGH;
                let st = tw_operation(
                    ops,
                    i,
                    &mut stage,
                    std::ptr::null_mut(),
                    std::ptr::null_mut(),
                    std::ptr::null_mut(),
                    std::ptr::null_mut(),
                    std::ptr::null_mut(),
                    std::ptr::null_mut(),
                );
                assert_eq!(st, tw_status::TW_OK);
                drills += usize::from(stage == tw_stage::TW_STAGE_DRILL);
            }
            // Five drilling operations, and a spot before the drills at
            // each of the two levels holes are entered from.
            assert_eq!(drills, 7);
            let name = CStr::from_ptr(tw_operation_tool(ops, 0)).to_str().unwrap();
            let first = &(&*ops).report.setup.operations[0];
            assert_eq!(name, first.tool);
            assert!(tw_operation_tool(ops, n).is_null());
            tw_operations_free(ops);

            let mut bad = std::ptr::null_mut();
            let toml = CString::new(
                "[[tool]]\nname = \"X\"\nkind = \"flat_end_mill\"\ndiameter = -4.0\ncutting_length = 10.0\nstick_out = 20.0\nteeth = 2\ncutting_speed_m_min = 300.0\nfeed_per_tooth_mm = 0.05\naxial_depth_mm = 2.0\nradial_depth_mm = 2.0\n",
            )
            .unwrap();
            let st = tw_operations(plate, std::ptr::null(), toml.as_ptr(), 0.0, &mut bad);
            assert_eq!(st, tw_status::TW_ERR_INVALID_CONFIG);
            assert!(bad.is_null());
            let msg = CStr::from_ptr(crate::tw_last_error_message())
                .to_str()
                .unwrap();
            assert!(
                msg.contains("tools_toml:1") && msg.contains("diameter"),
                "{msg}"
            );
            let st = tw_operations(plate, std::ptr::null(), std::ptr::null(), -1.0, &mut bad);
            assert_eq!(st, tw_status::TW_ERR_INVALID_ARGUMENT);
            tw_part_free(plate);

            // A turned panel's faces are tilted to the default up: meshed in
            // the removal, layered all the same, the JSON naming them.
            let turned = load("recognition/rib_grid_panel_turned.step");
            let mut ops = std::ptr::null_mut();
            let st = tw_operations(turned, std::ptr::null(), std::ptr::null(), 0.0, &mut ops);
            assert_eq!(st, tw_status::TW_OK);
            assert!(tw_operations_count(ops) > 0);
            let mut json = std::ptr::null_mut();
            assert_eq!(tw_operations_to_json(ops, &mut json), tw_status::TW_OK);
            let text = CStr::from_ptr(json).to_str().unwrap().to_string();
            crate::tw_string_free(json);
            assert!(text.contains("\"meshed\"") && text.contains("volume_bound_mm3"));
            tw_operations_free(ops);
            tw_part_free(turned);
            // A removal that does not add up is refused: NIST STC 08 with
            // its largest plane (#2926) left out of its shell.
            let path = format!(
                "{}/../../shared/data/nist/nist_stc_08_asme1_ap242-e3.stp",
                env!("CARGO_MANIFEST_DIR")
            );
            let text = std::fs::read_to_string(path).unwrap();
            let open = text.replacen("#2926,", "", 1);
            assert_ne!(open, text);
            let mut stc = std::ptr::null_mut();
            assert_eq!(
                crate::part::tw_part_load_memory(open.as_ptr(), open.len(), &mut stc),
                tw_status::TW_OK
            );
            refused(stc, "removal.inconsistent", "#");
        }
    }
}
