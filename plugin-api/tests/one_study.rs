//! A part keeps its study: calls on one `tw_part` share its analysis (and
//! mesh), so recognizing, planning and taking operations of a part builds
//! its analysis once in each set-up, and a repeated call computes nothing
//! again. Counted by `thinwall_brep::builds` on this thread (serial calls
//! build on the calling thread).

use std::ptr::{null, null_mut};
use thinwall::*;
use thinwall_brep::builds::{count, Built};

#[test]
fn calls_on_one_part_share_its_analysis() {
    let path = std::ffi::CString::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../fixtures/recognition/rib_grid_panel.step"
    ))
    .unwrap();
    unsafe {
        let mut part = null_mut();
        assert_eq!(
            tw_part_load_file(path.as_ptr(), &mut part),
            tw_status::TW_OK
        );
        let p = &*part;
        let built = || {
            (
                count(p.part(), Built::Analysis),
                count(p.part(), Built::Mesh),
            )
        };
        let mut opt = null_mut();
        assert_eq!(tw_options_new(&mut opt), tw_status::TW_OK);
        assert_eq!(tw_options_set_parallel(opt, false), tw_status::TW_OK);

        let mut res = null_mut();
        assert_eq!(tw_recognize(part, opt, &mut res), tw_status::TW_OK);
        assert_eq!(built(), (1, 0), "after tw_recognize");
        let mut plan = null_mut();
        assert_eq!(tw_plan(part, opt, null(), &mut plan), tw_status::TW_OK);
        assert_eq!(built().0, 1, "tw_plan reuses the analysis");
        let mut again = null_mut();
        assert_eq!(tw_recognize(part, opt, &mut again), tw_status::TW_OK);
        assert_eq!(built().0, 1, "a second tw_recognize reuses it");
        let json = |r| {
            let mut s = null_mut();
            assert_eq!(tw_result_to_json(r, &mut s), tw_status::TW_OK);
            s
        };
        let (a, b) = (json(res), json(again));
        assert_eq!(
            std::ffi::CStr::from_ptr(a),
            std::ffi::CStr::from_ptr(b),
            "the same result"
        );
        tw_string_free(a);
        tw_string_free(b);

        // Another set-up is another analysis, once.
        assert_eq!(tw_options_set_up(opt, 0.0, 0.0, -1.0), tw_status::TW_OK);
        let mut other = null_mut();
        assert_eq!(tw_recognize(part, opt, &mut other), tw_status::TW_OK);
        assert_eq!(built().0, 2, "the second set-up's analysis");
        let mut other_plan = null_mut();
        assert_eq!(
            tw_plan(part, opt, null(), &mut other_plan),
            tw_status::TW_OK
        );
        assert_eq!(built().0, 2, "its plan reuses it");

        // Results outlive nothing of the part: freed after the part, they
        // still read (they own their data).
        tw_part_free(part);
        let mut text = null_mut();
        assert_eq!(tw_plan_to_json(plan, &mut text), tw_status::TW_OK);
        assert!(!text.is_null());
        tw_string_free(text);
        for r in [res, again, other] {
            tw_result_free(r);
        }
        tw_plan_free(plan);
        tw_plan_free(other_plan);
        tw_options_free(opt);
    }
}
