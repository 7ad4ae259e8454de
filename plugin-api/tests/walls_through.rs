//! `tw_result_feature_other_side`: a wall through its base (a generated
//! panel pocketed from both sides of its web) gives its height on the
//! web's other side, as the JSON's `other_side` has it; a web, a hole and
//! a wall on one side of its base are `TW_ERR_NOT_APPLICABLE`.

use std::ffi::CStr;
use std::ptr::null_mut;
use thinwall::*;

#[test]
fn other_side_of_walls_through_a_web() {
    let path = std::ffi::CString::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../fixtures/pockets/pockets_6.step"
    ))
    .unwrap();
    unsafe {
        let mut part = null_mut();
        assert_eq!(
            tw_part_load_file(path.as_ptr(), &mut part),
            tw_status::TW_OK
        );
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
