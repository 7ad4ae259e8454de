//! Double-sided panels through the C ABI. `tw_result_feature_other_side`:
//! a wall through its base (a generated panel pocketed from both sides of
//! its web) gives its height on the web's other side, as the JSON's
//! `other_side` has it; a web, a hole and a wall on one side of its base
//! are `TW_ERR_NOT_APPLICABLE`. `tw_operations_both_sides` and
//! `tw_operations_second` plan and read both set-ups;
//! `tw_operations_setups` and `tw_plan_setups` plan given or proposed
//! set-ups in turn.

use std::ffi::CStr;
use std::ptr::null_mut;
use thinwall_capi::*;

/// The generated panel pocketed from both sides of its web, read.
unsafe fn panel() -> *mut tw_part {
    let path = std::ffi::CString::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../fixtures/pockets/pockets_6.step"
    ))
    .unwrap();
    let mut part = null_mut();
    assert_eq!(
        tw_part_load_file(path.as_ptr(), &mut part),
        tw_status::TW_OK
    );
    part
}

#[test]
fn other_side_of_walls_through_a_web() {
    unsafe {
        let part = panel();
        let mut opt = null_mut();
        assert_eq!(tw_options_new(&mut opt), tw_status::TW_OK);
        let mut res = null_mut();
        assert_eq!(tw_recognize(part, opt, &mut res), tw_status::TW_OK);
        let mut json = null_mut();
        assert_eq!(tw_result_to_json(res, &mut json), tw_status::TW_OK);
        let report: serde_json::Value =
            serde_json::from_str(CStr::from_ptr(json).to_str().unwrap()).unwrap();
        tw_string_free(json);
        let features = report["stiffness_features"].as_array().unwrap();
        assert_eq!(features.len(), tw_result_feature_count(res));
        let mut through = 0;
        for (i, f) in features.iter().enumerate() {
            let (mut h, mut thin) = (f64::NAN, false);
            let status = tw_result_feature_other_side(res, i, &mut h, &mut thin);
            match f.get("other_side") {
                Some(o) => {
                    through += 1;
                    assert_eq!(status, tw_status::TW_OK, "{}", f["id"]);
                    // The JSON writes 15 significant digits.
                    assert!((h - o["height"].as_f64().unwrap()).abs() < 1e-9, "{h}");
                    assert_eq!(thin, o["thin"].as_bool().unwrap());
                }
                None => assert_eq!(status, tw_status::TW_ERR_NOT_APPLICABLE, "{}", f["id"]),
            }
        }
        // Two ribs and four outer walls run through the web.
        assert_eq!(through, 6);
        let n = tw_result_feature_count(res);
        assert_eq!(
            tw_result_feature_other_side(res, n, null_mut(), null_mut()),
            tw_status::TW_ERR_OUT_OF_RANGE
        );
        assert_eq!(
            tw_result_feature_other_side(std::ptr::null(), 0, null_mut(), null_mut()),
            tw_status::TW_ERR_NULL_ARGUMENT
        );
        tw_result_free(res);
        tw_options_free(opt);
        tw_part_free(part);
    }
}

/// `tw_operations_both_sides` on the same panel: the first set-up leaves
/// material under the web (`tw_operations_volumes`), the second, read
/// with `tw_operations_second`, takes nothing before it was cleared and
/// has operations of its own; its JSON is its own report (up reversed).
/// A one-set-up result has no second side.
#[test]
fn both_sides_of_a_double_sided_panel() {
    unsafe {
        let part = panel();
        let mut first = null_mut();
        assert_eq!(
            tw_operations_both_sides(part, std::ptr::null(), std::ptr::null(), 0.0, &mut first),
            tw_status::TW_OK
        );
        let (mut left, mut cleared) = (f64::NAN, f64::NAN);
        assert_eq!(
            tw_operations_volumes(first, &mut left, &mut cleared),
            tw_status::TW_OK
        );
        assert!(left > 0.0 && cleared == 0.0, "{left} {cleared}");
        let mut second = null_mut();
        assert_eq!(tw_operations_second(first, &mut second), tw_status::TW_OK);
        let (mut left2, mut cleared2) = (f64::NAN, f64::NAN);
        assert_eq!(
            tw_operations_volumes(second, &mut left2, &mut cleared2),
            tw_status::TW_OK
        );
        assert!(left2 == 0.0 && cleared2 > 0.0, "{left2} {cleared2}");
        assert!(tw_operations_count(second) > 0);
        let mut json = null_mut();
        assert_eq!(tw_operations_to_json(second, &mut json), tw_status::TW_OK);
        let report: serde_json::Value =
            serde_json::from_str(CStr::from_ptr(json).to_str().unwrap()).unwrap();
        tw_string_free(json);
        assert_eq!(report["up"][2], -1.0);
        assert!(report.get("then").is_none());
        // One set-up: no second side.
        let mut one = null_mut();
        assert_eq!(
            tw_operations(part, std::ptr::null(), std::ptr::null(), 0.0, &mut one),
            tw_status::TW_OK
        );
        let mut none = null_mut();
        assert_eq!(
            tw_operations_second(one, &mut none),
            tw_status::TW_ERR_NOT_APPLICABLE
        );
        assert!(none.is_null());
        for r in [first, second, one] {
            tw_operations_free(r);
        }
        tw_part_free(part);
    }
}

/// `tw_operations_setups` on the same panel: proposed (no ups), two set-ups
/// from opposite sides along the web's normal, nothing left that neither
/// reaches; given the same two ups in order, the same operations; read
/// one by one with `tw_operations_setup_at`, out of range past the last;
/// a count of ups without the array is refused.
/// `tw_operations_setups` on `part` with `n` ups from `ups` (NULL when
/// empty and `n` 0): its status and result.
unsafe fn setups(
    part: *mut tw_part,
    ups: &[f64],
    n: usize,
) -> (tw_status, *mut tw_operations_result) {
    let mut out = null_mut();
    let given = if ups.is_empty() {
        std::ptr::null()
    } else {
        ups.as_ptr()
    };
    let status = tw_operations_setups(
        part,
        std::ptr::null(),
        given,
        n,
        std::ptr::null(),
        0.0,
        &mut out,
    );
    (status, out)
}

#[test]
fn set_ups_proposed_and_given() {
    unsafe {
        let part = panel();
        let (status, proposed) = setups(part, &[], 0);
        assert_eq!(status, tw_status::TW_OK);
        let mut n = 0usize;
        assert_eq!(
            tw_operations_setup_count(proposed, &mut n),
            tw_status::TW_OK
        );
        assert_eq!(n, 2);
        let mut residue = f64::NAN;
        assert_eq!(
            tw_operations_residue(proposed, &mut residue),
            tw_status::TW_OK
        );
        assert!(residue.abs() < 1e-3, "{residue}");
        let ups_of = |r: *mut tw_operations_result| -> Vec<(f64, usize)> {
            (0..2)
                .map(|k| {
                    let mut one = null_mut();
                    assert_eq!(tw_operations_setup_at(r, k, &mut one), tw_status::TW_OK);
                    let mut json = null_mut();
                    assert_eq!(tw_operations_to_json(one, &mut json), tw_status::TW_OK);
                    let v: serde_json::Value =
                        serde_json::from_str(CStr::from_ptr(json).to_str().unwrap()).unwrap();
                    tw_string_free(json);
                    let count = tw_operations_count(one);
                    tw_operations_free(one);
                    (v["up"][2].as_f64().unwrap(), count)
                })
                .collect()
        };
        let got = ups_of(proposed);
        assert_eq!(got[0].0, -got[1].0);
        assert_eq!(got[0].0.abs(), 1.0);
        let ups = [0.0, 0.0, got[0].0, 0.0, 0.0, got[1].0];
        let (status, given) = setups(part, &ups, 2);
        assert_eq!(status, tw_status::TW_OK);
        assert_eq!(ups_of(given), got);
        let mut past = null_mut();
        assert_eq!(
            tw_operations_setup_at(given, 2, &mut past),
            tw_status::TW_ERR_OUT_OF_RANGE
        );
        assert!(past.is_null());
        let (status, refused) = setups(part, &[], 2);
        assert_eq!(status, tw_status::TW_ERR_NULL_ARGUMENT);
        assert!(refused.is_null());
        for r in [proposed, given] {
            tw_operations_free(r);
        }
        tw_part_free(part);
    }
}

/// `tw_plan_setups` on `part` with `n` ups from `ups` (NULL when empty).
unsafe fn plan_setups(
    part: *mut tw_part,
    ups: &[f64],
    n: usize,
) -> (tw_status, *mut tw_plan_result) {
    let mut out = null_mut();
    let given = if ups.is_empty() {
        std::ptr::null()
    } else {
        ups.as_ptr()
    };
    let status = tw_plan_setups(part, std::ptr::null(), given, n, std::ptr::null(), &mut out);
    (status, out)
}

/// A plan's JSON.
unsafe fn plan_json(p: *const tw_plan_result) -> serde_json::Value {
    let mut json = null_mut();
    assert_eq!(tw_plan_to_json(p, &mut json), tw_status::TW_OK);
    let v = serde_json::from_str(CStr::from_ptr(json).to_str().unwrap()).unwrap();
    tw_string_free(json);
    v
}

/// `tw_plan_setups` on the same panel: proposed, two set-ups from opposite
/// sides, the second's removal holding what the first took as cleared
/// (its features and that add up to stock − part), nothing left; given
/// the same ups in order, the same plans; each set-up read on its own with
/// `tw_plan_setup_at`, out of range past the last.
#[test]
fn plans_of_set_ups_proposed_and_given() {
    unsafe {
        let part = panel();
        let (status, proposed) = plan_setups(part, &[], 0);
        assert_eq!(status, tw_status::TW_OK);
        let mut n = 0usize;
        assert_eq!(tw_plan_setup_count(proposed, &mut n), tw_status::TW_OK);
        assert_eq!(n, 2);
        let whole = plan_json(proposed);
        assert!(whole["residue"]["volume_mm3"].as_f64().unwrap() < 1e-3);
        assert_eq!(whole["then"].as_array().unwrap().len(), 1);
        let second = &whole["then"][0]["removal"];
        let taken = second["cleared_before_mm3"].as_f64().unwrap();
        let own = second["removed_volume_mm3"].as_f64().unwrap();
        let stock_part = second["stock_volume_mm3"].as_f64().unwrap()
            - second["part_volume_mm3"].as_f64().unwrap();
        assert!(taken > 0.0 && own > 0.0);
        assert!(
            (taken + own - stock_part).abs() < 1e-6 * stock_part + 1.0,
            "{taken} + {own} vs {stock_part}"
        );
        let ups_of = |r: *mut tw_plan_result| -> Vec<(f64, usize)> {
            (0..2)
                .map(|k| {
                    let mut one = null_mut();
                    assert_eq!(tw_plan_setup_at(r, k, &mut one), tw_status::TW_OK);
                    let v = plan_json(one);
                    assert!(v.get("then").is_none());
                    let features = v["machining_features"].as_array().unwrap().len();
                    tw_plan_free(one);
                    (v["up"][2].as_f64().unwrap(), features)
                })
                .collect()
        };
        let got = ups_of(proposed);
        assert_eq!(got[0].0, -got[1].0);
        let ups = [0.0, 0.0, got[0].0, 0.0, 0.0, got[1].0];
        let (status, given) = plan_setups(part, &ups, 2);
        assert_eq!(status, tw_status::TW_OK);
        assert_eq!(ups_of(given), got);
        let mut past = null_mut();
        assert_eq!(
            tw_plan_setup_at(given, 2, &mut past),
            tw_status::TW_ERR_OUT_OF_RANGE
        );
        assert!(past.is_null());
        let (status, refused) = plan_setups(part, &[], 2);
        assert_eq!(status, tw_status::TW_ERR_NULL_ARGUMENT);
        assert!(refused.is_null());
        for r in [proposed, given] {
            tw_plan_free(r);
        }
        tw_part_free(part);
    }
}
