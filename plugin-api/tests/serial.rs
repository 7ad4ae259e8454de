//! `parallel` false is honoured by every call that takes options: no
//! thread is started (this test binary runs nothing else, so rayon's pool
//! would appear in `/proc/self/task` if anything started it).

use std::ptr::null_mut;
use thinwall_capi::*;

fn threads() -> usize {
    std::fs::read_dir("/proc/self/task").map_or(0, |d| d.count())
}

#[test]
fn serial_calls_start_no_thread() {
    let before = threads();
    assert!(before > 0, "/proc/self/task is readable");
    let path = std::ffi::CString::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../fixtures/recognition/c_frame.step"
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
        assert_eq!(tw_options_set_parallel(opt, false), tw_status::TW_OK);
        let mut res = null_mut();
        assert_eq!(tw_recognize(part, opt, &mut res), tw_status::TW_OK);
        tw_result_free(res);
        assert_eq!(threads(), before, "after tw_result");
        let mut plan = null_mut();
        assert_eq!(
            tw_plan(part, opt, std::ptr::null(), &mut plan),
            tw_status::TW_OK
        );
        tw_plan_free(plan);
        assert_eq!(threads(), before, "after tw_plan");
        let mut access = null_mut();
        assert_eq!(
            tw_access(part, opt, 12.0, 0.5, &mut access),
            tw_status::TW_OK
        );
        tw_access_free(access);
        assert_eq!(threads(), before, "after tw_access");
        let mut ops = null_mut();
        let status = tw_operations(part, opt, std::ptr::null(), 0.0, &mut ops);
        assert!(
            matches!(status, tw_status::TW_OK | tw_status::TW_ERR_UNSUPPORTED),
            "{status:?}"
        );
        tw_operations_free(ops);
        assert_eq!(threads(), before, "after tw_operations");
        let volumes = [part as *const tw_part];
        let mut classified = null_mut();
        let _ = tw_classify(
            part,
            volumes.as_ptr(),
            1,
            std::ptr::null(),
            0,
            opt,
            &mut classified,
        );
        tw_classification_free(classified);
        assert_eq!(threads(), before, "after tw_classification");
        tw_options_free(opt);
        tw_part_free(part);
    }
    assert_eq!(threads(), before, "a serial call started a thread");
}
