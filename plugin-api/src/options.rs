//! `tw_options`: the set-up and recognition settings. Filled by the caller
//! before use; do not change an options object while another thread uses it.

use crate::error::{construct, free, guard, null, tw_status};
use thinwall_analysis::{Machine, Setup};
use thinwall_pipeline::Request;

/// Recognition settings (opaque): the set-up, the recognition settings and
/// the connection options. Defaults: up +Z, 3-axis machine, Popma's sizing
/// parameters (F 200 N, E 70 000 N/mm², δ 0.01 mm, Ø12 tool), and no
/// worker threads inside a call (a host runs its own threads).
#[derive(Clone)]
pub struct tw_options {
    pub(crate) request: Request,
}

impl Default for tw_options {
    fn default() -> Self {
        Self {
            request: Request {
                parallel: false,
                ..Request::default()
            },
        }
    }
}

/// The options at `opt`, or the defaults for NULL.
pub(crate) unsafe fn options_or_default<'a>(
    opt: *const tw_options,
) -> std::borrow::Cow<'a, tw_options> {
    if opt.is_null() {
        std::borrow::Cow::Owned(tw_options::default())
    } else {
        std::borrow::Cow::Borrowed(&*opt)
    }
}

/// New options with the defaults; free with `tw_options_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_options_new(out: *mut *mut tw_options) -> tw_status {
    construct("tw_options_new", out, || Ok(tw_options::default()))
}

/// Change options; a change that fails (or panics) leaves them as they were.
unsafe fn with(
    opt: *mut tw_options,
    f: impl FnOnce(&mut tw_options) -> Result<(), String>,
) -> tw_status {
    guard("tw_options_set", || {
        if opt.is_null() {
            return Err(null("opt"));
        }
        let o = &mut *opt;
        // Work on a copy and commit it only when it is valid: a panic in
        // `f` unwinds past the copy and leaves `*o` untouched.
        let mut next = o.clone();
        f(&mut next).map_err(|m| (tw_status::TW_ERR_INVALID_ARGUMENT, m))?;
        // The request's own rules, the same the CLI's flags meet.
        next.request
            .check()
            .map_err(|e| (tw_status::TW_ERR_INVALID_ARGUMENT, e.to_string()))?;
        *o = next;
        Ok(())
    })
}

/// The set-up's up direction (tool axis); need not be unit length, must not
/// be zero. Machining features are then judged in the set-up (entered from
/// up where they open there; each says whether the tool reaches it).
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_up(
    opt: *mut tw_options,
    x: f64,
    y: f64,
    z: f64,
) -> tw_status {
    with(opt, |o| {
        let s = Setup::new([x, y, z], o.request.setup.machine).map_err(|e| e.to_string())?;
        o.request.setup = s;
        o.request.machining.in_setup = true;
        Ok(())
    })
}

/// A uniform allowance on the part's block, mm (0 or more): the part's
/// faces on the block become facing features.
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_stock_offset(opt: *mut tw_options, mm: f64) -> tw_status {
    with(opt, |o| {
        o.request.machining.stock_offset = mm;
        Ok(())
    })
}

/// Maximum milling force, N (> 0).
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_force(opt: *mut tw_options, newton: f64) -> tw_status {
    with(opt, |o| {
        o.request.config.thinness.force_n = newton;
        Ok(())
    })
}

/// Young's modulus of the material, N/mm² (> 0).
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_youngs_modulus(
    opt: *mut tw_options,
    n_per_mm2: f64,
) -> tw_status {
    with(opt, |o| {
        o.request.config.thinness.youngs_modulus_n_mm2 = n_per_mm2;
        Ok(())
    })
}

/// Allowed wall deflection, mm (> 0).
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_allowed_deflection(
    opt: *mut tw_options,
    mm: f64,
) -> tw_status {
    with(opt, |o| {
        o.request.config.thinness.allowed_deflection_mm = mm;
        Ok(())
    })
}

/// Preferred tool diameter, mm (> 0): large holes are higher than 1.5 × it.
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_tool_diameter(opt: *mut tw_options, mm: f64) -> tw_status {
    with(opt, |o| {
        o.request.config.thresholds.preferred_tool_diameter_mm = mm;
        Ok(())
    })
}

/// Use a 5-axis machine whose tool axis tilts at most `tilt_limit_deg` (0–90)
/// from up; a negative value goes back to 3 axes.
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_five_axis(
    opt: *mut tw_options,
    tilt_limit_deg: f64,
) -> tw_status {
    with(opt, |o| {
        if tilt_limit_deg < 0.0 {
            o.request.setup.machine = Machine::ThreeAxis;
            return Ok(());
        }
        o.request.setup.machine = Machine::FiveAxis { tilt_limit_deg };
        Ok(())
    })
}

/// Link thin walls to the thick walls they stand on (default false).
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_connect_thick(
    opt: *mut tw_options,
    connect: bool,
) -> tw_status {
    with(opt, |o| {
        o.request.connect.connect_thick_walls = connect;
        Ok(())
    })
}

/// Let a call use Thinwall's worker threads (rayon, one per core) for the
/// costly parts of recognition (default false: a call runs on the calling
/// thread only). The results are the same either way.
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_parallel(
    opt: *mut tw_options,
    parallel: bool,
) -> tw_status {
    with(opt, |o| {
        o.request.parallel = parallel;
        Ok(())
    })
}

/// Recognize parts whose shell is open (edges used by one face only)
/// instead of refusing them with `TW_ERR_INVALID_PART` (default false).
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_allow_open(opt: *mut tw_options, allow: bool) -> tw_status {
    with(opt, |o| {
        o.request.allow_open = allow;
        Ok(())
    })
}

/// Free options. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_options_free(opt: *mut tw_options) {
    free(opt)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_failed_or_panicking_change_leaves_the_options_as_they_were() {
        let mut o = tw_options::default();
        let p: *mut tw_options = &mut o;
        unsafe {
            assert_eq!(tw_options_set_force(p, 150.0), tw_status::TW_OK);
            // Invalid: rolled back.
            assert_eq!(
                tw_options_set_force(p, -1.0),
                tw_status::TW_ERR_INVALID_ARGUMENT
            );
            assert_eq!(
                tw_options_set_up(p, 0.0, 0.0, 0.0),
                tw_status::TW_ERR_INVALID_ARGUMENT
            );
            // A panic half-way through a change: caught, and nothing changed.
            let st = with(p, |o| {
                o.request.config.thinness.force_n = 10.0;
                o.request.setup.up = [1.0, 0.0, 0.0];
                panic!("half-way");
            });
            assert_eq!(st, tw_status::TW_ERR_PANIC);
        }
        assert_eq!(o.request.config.thinness.force_n, 150.0);
        assert_eq!(o.request.setup.up, [0.0, 0.0, 1.0]);
        assert!(unsafe { tw_options_set_up(&mut o, 0.0, 2.0, 0.0) } == tw_status::TW_OK);
        assert_eq!(o.request.setup.up, [0.0, 1.0, 0.0]);
    }
}
