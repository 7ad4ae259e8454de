//! `tw_options`: the set-up and recognition settings. Filled by the caller
//! before use; do not change an options object while another thread uses it.

use crate::error::{construct, free, guard, null, tw_status};
use thinwall_connect::{Machine, Options, Setup};
use thinwall_recognize::Config;

/// Recognition settings (opaque). Defaults: up +Z, 3-axis machine,
/// Popma's sizing parameters (F 200 N, E 70 000 N/mm², δ 0.01 mm, Ø12 tool).
pub struct tw_options {
    pub(crate) config: Config,
    pub(crate) machine: Machine,
    pub(crate) connect: Options,
}

impl Default for tw_options {
    fn default() -> Self {
        Self {
            config: Config::default(),
            machine: Machine::ThreeAxis,
            connect: Options::default(),
        }
    }
}

impl tw_options {
    pub(crate) fn setup(&self) -> Setup {
        let u = self.config.up_unit();
        Setup {
            up: [u.x, u.y, u.z],
            machine: self.machine,
            placement: None,
        }
    }
}

/// New options with the defaults; free with `tw_options_free`.
#[no_mangle]
pub unsafe extern "C" fn tw_options_new(out: *mut *mut tw_options) -> tw_status {
    construct(out, || Ok(tw_options::default()))
}

unsafe fn with(
    opt: *mut tw_options,
    f: impl FnOnce(&mut tw_options) -> Result<(), String>,
) -> tw_status {
    guard(|| {
        if opt.is_null() {
            return Err(null("opt"));
        }
        let o = &mut *opt;
        let before = o.config.clone();
        f(o).map_err(|m| (tw_status::TW_ERR_INVALID_ARGUMENT, m))?;
        if let Err(e) = o.config.validate() {
            o.config = before;
            return Err((tw_status::TW_ERR_INVALID_ARGUMENT, e.to_string()));
        }
        Ok(())
    })
}

/// The set-up's up direction (tool axis); need not be unit length, must not be zero.
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_up(
    opt: *mut tw_options,
    x: f64,
    y: f64,
    z: f64,
) -> tw_status {
    with(opt, |o| {
        o.config.up = [x, y, z];
        Ok(())
    })
}

/// Maximum milling force, N (> 0).
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_force(opt: *mut tw_options, newton: f64) -> tw_status {
    with(opt, |o| {
        o.config.thinness.force_n = newton;
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
        o.config.thinness.youngs_modulus_n_mm2 = n_per_mm2;
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
        o.config.thinness.allowed_deflection_mm = mm;
        Ok(())
    })
}

/// Preferred tool diameter, mm (> 0): large holes are higher than 1.5 × it.
#[no_mangle]
pub unsafe extern "C" fn tw_options_set_tool_diameter(opt: *mut tw_options, mm: f64) -> tw_status {
    with(opt, |o| {
        o.config.thresholds.preferred_tool_diameter_mm = mm;
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
            o.machine = Machine::ThreeAxis;
            return Ok(());
        }
        if !(tilt_limit_deg.is_finite() && tilt_limit_deg <= 90.0) {
            return Err(format!(
                "tilt limit must be within 0..90 degrees, got {tilt_limit_deg}"
            ));
        }
        o.machine = Machine::FiveAxis { tilt_limit_deg };
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
        o.connect.connect_thick_walls = connect;
        Ok(())
    })
}

/// Free options. NULL is allowed.
#[no_mangle]
pub unsafe extern "C" fn tw_options_free(opt: *mut tw_options) {
    free(opt)
}
