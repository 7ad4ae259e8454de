//! The machining-feature sizing model (DOMAIN.md §5.1, Popma §4.1.2, table
//! 4.1, App. A): the width `B_RF` of the material left beside a thin wall,
//! and the heights `h_RF` (small features, one side) and `H_RF` (large
//! features, the other side) of the step approach.
//!
//! **The bending model.** The worst moment of the step approach: the first
//! large feature (height `H`) is gone on one side, the first small one
//! (height `h`) nearly finished on the other. The wall is a cantilever on
//! its rigid base, of effective length `min(L, factor · wall height)`, in
//! three sections from the base up: below `H`, the wall and `B` of support
//! on each side (`t + 2B`); from `H` to `h`, the wall and the small side's
//! support (`t + B`); above `h`, the bare wall (`t`). The milling force `F`
//! acts at the top of the last finishing cut (`h −` one cut below the
//! top); the deflection is taken at the top of the tool's vibration
//! re-machining zone above it (¾·D peripheral, ½·D face milling): the
//! force point's deflection plus its slope times the zone. (Where Popma's
//! figure 4.3 is not reproduced in text, these are our reading of it; see
//! `docs/PLANNING.md`.)
//!
//! **The iteration.** Initial sizes from the rules of thumb; while the
//! deflection is too large, `h` loses one finishing cut (down to one cut)
//! and `H` is reset to its initial multiple of `h`, then (`h` at one cut)
//! `B` grows by one roughing step; once within the limit, `H` grows by `h` while it stays
//! within the limit and the wall. Sizes are rounded as table 4.1 (widths
//! up, heights down).
//!
//! **From the Fokker tests** (App. A.1, test 10): `H = 4·h` was good on a
//! 48 mm wall and vibrated on a 72 mm wall (120 × 1 mm), where `H = 3·h`
//! was good: "this ratio is too great if the wall height exceeds 4·h". The
//! model caps `H` at `tall_wall_max_ratio · h` (3) on walls higher than
//! `4·h`; the pure bending model alone allows 48 there (0.0088 mm).

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// How the wall's machining features are milled.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Milling {
    /// With the tool's flank (ribs, flanges, walls).
    Peripheral,
    /// With the tool's end (webs).
    Face,
}

/// Every parameter of the model, defaults from App. A.2 (aluminium).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SizingParameters {
    pub milling: Milling,
    /// Allowed deflection, mm.
    pub allowed_deflection_mm: f64,
    /// Effective length over wall height.
    pub effective_length_factor: f64,
    /// Largest milling force, N.
    pub force_n: f64,
    /// Young's modulus, N/mm².
    pub youngs_modulus_n_mm2: f64,
    /// Preferred tool diameter, mm.
    pub tool_diameter_mm: f64,
    /// Initial `H_RF / h_RF`.
    pub initial_height_ratio: f64,
    /// Vibration re-machining zone over the tool diameter (¾ peripheral,
    /// ½ face).
    pub zone_per_diameter: f64,
    /// Peripheral: finishing width of cut (mm); face: finishing depth of
    /// cut (mm). The fixed part of a width.
    pub finishing_width_mm: f64,
    /// Peripheral: roughing stepover over D; face: roughing depth (mm).
    /// One step of a width.
    pub roughing_step: f64,
    /// One cut of a height: peripheral the finishing depth of cut (mm);
    /// face the finishing width of cut (½·D + 1 mm).
    pub cut_height_mm: f64,
    /// Initial number of cuts in `h_RF`.
    pub initial_cuts: u32,
    /// Initial number of roughing steps in `B_RF` (peripheral 1: two cuts;
    /// face 2: three cuts).
    pub initial_width_steps: u32,
    /// On walls higher than 4·h: `H_RF` at most this times `h_RF`
    /// (Fokker test 10).
    pub tall_wall_max_ratio: f64,
}

impl SizingParameters {
    /// App. A.2's values for `milling`.
    pub fn defaults(milling: Milling) -> Self {
        let d = 12.0;
        let (zone, fin, step, cut, cuts, steps) = match milling {
            Milling::Peripheral => (0.75, 2.0, 0.75, 1.5, 8, 1),
            Milling::Face => (0.5, 2.0, 4.0, 0.5 * d + 1.0, 3, 2),
        };
        Self {
            milling,
            allowed_deflection_mm: 0.01,
            effective_length_factor: 4.0,
            force_n: 200.0,
            youngs_modulus_n_mm2: 70_000.0,
            tool_diameter_mm: d,
            initial_height_ratio: 2.0,
            zone_per_diameter: zone,
            finishing_width_mm: fin,
            roughing_step: step,
            cut_height_mm: cut,
            initial_cuts: cuts,
            initial_width_steps: steps,
            tall_wall_max_ratio: 3.0,
        }
    }

    /// One roughing step of a width, mm.
    fn width_step(&self) -> f64 {
        match self.milling {
            Milling::Peripheral => self.roughing_step * self.tool_diameter_mm,
            Milling::Face => self.roughing_step,
        }
    }

    fn zone(&self) -> f64 {
        self.zone_per_diameter * self.tool_diameter_mm
    }

    fn validate(&self) -> Result<(), SizingError> {
        let positive = [
            ("allowed_deflection_mm", self.allowed_deflection_mm),
            ("effective_length_factor", self.effective_length_factor),
            ("force_n", self.force_n),
            ("youngs_modulus_n_mm2", self.youngs_modulus_n_mm2),
            ("tool_diameter_mm", self.tool_diameter_mm),
            ("initial_height_ratio", self.initial_height_ratio),
            ("finishing_width_mm", self.finishing_width_mm),
            ("roughing_step", self.roughing_step),
            ("cut_height_mm", self.cut_height_mm),
            ("tall_wall_max_ratio", self.tall_wall_max_ratio),
        ];
        for (name, v) in positive {
            if !(v.is_finite() && v > 0.0) {
                return Err(SizingError::Parameter { name, value: v });
            }
        }
        if !(self.zone_per_diameter.is_finite() && self.zone_per_diameter >= 0.0) {
            return Err(SizingError::Parameter {
                name: "zone_per_diameter",
                value: self.zone_per_diameter,
            });
        }
        if self.initial_cuts == 0 {
            return Err(SizingError::Parameter {
                name: "initial_cuts",
                value: 0.0,
            });
        }
        Ok(())
    }
}

/// A wall: length, thickness, height, mm.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct WallDimensions {
    pub length: f64,
    pub thickness: f64,
    pub height: f64,
}

/// One step of the iteration.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Step {
    #[serde(rename = "B_RF")]
    pub b: f64,
    #[serde(rename = "h_RF")]
    pub h: f64,
    #[serde(rename = "H_RF")]
    pub big_h: f64,
    pub deflection_mm: f64,
    pub action: String,
}

/// The sizes of a wall's machining features.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Sizes {
    /// Width of the material left beside the wall, mm.
    #[serde(rename = "B_RF")]
    pub b: f64,
    /// Small feature height, mm.
    #[serde(rename = "h_RF")]
    pub h: f64,
    /// Large feature height, mm.
    #[serde(rename = "H_RF")]
    pub big_h: f64,
    /// Deflection at these sizes, mm.
    pub deflection_mm: f64,
    pub milling: Milling,
    /// Whether the wall needs the step approach at all.
    pub thin: bool,
    pub note: String,
    pub wall: WallDimensions,
    pub parameters: SizingParameters,
    pub trace: Vec<Step>,
}

impl Sizes {
    /// The sizes and the iteration, for a planner to read.
    pub fn to_text(&self) -> String {
        use std::fmt::Write;
        let w = &self.wall;
        let mut s = String::new();
        let _ = writeln!(
            s,
            "wall {} x {} x {} mm, {:?} milling: {}",
            w.length, w.thickness, w.height, self.milling, self.note
        );
        let _ = writeln!(
            s,
            "  B_RF {} mm, h_RF {} mm, H_RF {} mm, deflection {:.4} mm (allowed {})",
            self.b, self.h, self.big_h, self.deflection_mm, self.parameters.allowed_deflection_mm
        );
        let _ = writeln!(s, "  iteration:");
        for st in &self.trace {
            let _ = writeln!(
                s,
                "    B {:>6.2}  h {:>6.2}  H {:>6.2}  deflection {:.4}  {}",
                st.b, st.h, st.big_h, st.deflection_mm, st.action
            );
        }
        s
    }
}

/// Sizes that cannot be computed.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum SizingError {
    #[error("wall {name} must be a positive length in mm, got {value}")]
    Dimension { name: &'static str, value: f64 },
    #[error("parameter {name} out of range: {value}")]
    Parameter { name: &'static str, value: f64 },
}

impl SizingError {
    pub fn code(&self) -> &'static str {
        match self {
            SizingError::Dimension { .. } => "sizing.dimension",
            SizingError::Parameter { .. } => "sizing.parameter",
        }
    }
}

/// A support width that stands for "rigid", mm.
const UNBOUNDED_SUPPORT_MM: f64 = 1e6;

use thinwall_geom::tolerance::SAME_LENGTH_MM;
/// The most steps the width may grow before the model gives up.
const MAX_WIDTH_STEPS: u32 = 50;

/// Deflection (mm) at the top of the vibration zone for sizes `b`, `h`,
/// `big_h` (module docs).
pub fn deflection(w: &WallDimensions, p: &SizingParameters, b: f64, h: f64, big_h: f64) -> f64 {
    let l_eff = w.length.min(p.effective_length_factor * w.height);
    let inertia = |thickness: f64| l_eff * thickness.powi(3) / 12.0;
    // Heights measured from the base up; the force point's height.
    let top = w.height;
    let force_at = (top - (h - p.cut_height_mm).max(0.0)).max(0.0);
    let sections = [
        (0.0, (top - big_h).max(0.0), w.thickness + 2.0 * b),
        ((top - big_h).max(0.0), (top - h).max(0.0), w.thickness + b),
        ((top - h).max(0.0), force_at, w.thickness),
    ];
    let (mut slope, mut deflection) = (0.0, 0.0);
    for (from, to, thickness) in sections {
        let (from, to) = (from.min(force_at), to.min(force_at));
        if to <= from {
            continue;
        }
        // M(x) = F (force_at − x); slope += ∫ M/EI, deflection += ∫ M (force_at − x)/EI.
        let ei = p.youngs_modulus_n_mm2 * inertia(thickness);
        let (a, c) = (force_at - from, force_at - to);
        slope += p.force_n * (a * a - c * c) / 2.0 / ei;
        deflection += p.force_n * (a.powi(3) - c.powi(3)) / 3.0 / ei;
    }
    deflection + slope * p.zone()
}

/// Size the machining features of a wall (module docs).
pub fn size_wall(w: &WallDimensions, p: &SizingParameters) -> Result<Sizes, SizingError> {
    for (name, value) in [
        ("length", w.length),
        ("thickness", w.thickness),
        ("height", w.height),
    ] {
        if !(value.is_finite() && value > 0.0) {
            return Err(SizingError::Dimension { name, value });
        }
    }
    p.validate()?;
    let cut = p.cut_height_mm;
    let mut search = Search {
        w,
        p,
        trace: Vec::new(),
    };
    // Not thin: cut in one go (no support), the wall stays within the limit.
    let whole = search.round_height(w.height).min(w.height);
    // The bare wall with the force at its top (as the recognizer's
    // thinness): within the limit, it needs no step approach.
    if search.log(0.0, cut, cut, "bare wall, force at its top") <= p.allowed_deflection_mm {
        let note = "not thin: one feature over its height, no step approach".to_string();
        return Ok(finish(w, p, 0.0, whole, whole, false, note, search.trace));
    }
    let steps = p.initial_width_steps.max(1);
    // The bare top above one cut bends whatever the support below: if
    // that alone exceeds the limit, no width helps.
    if deflection(w, p, UNBOUNDED_SUPPORT_MM, cut, cut) > p.allowed_deflection_mm {
        search.log(
            UNBOUNDED_SUPPORT_MM,
            cut,
            cut,
            "even one cut on an unbounded support bends too much",
        );
        let note = format!(
            "no sizes keep the deflection within {} mm: even one {cut} mm cut on a rigid support bends more; the wall needs other measures (a lower force, a stiffer set-up)",
            p.allowed_deflection_mm
        );
        return Ok(finish(
            w,
            p,
            search.width(steps),
            cut,
            cut,
            true,
            note,
            search.trace,
        ));
    }
    let (steps, h, big_h) = match search.fit(steps) {
        Ok(found) => found,
        Err(((steps, h, big_h), note)) => {
            let b = search.width(steps);
            return Ok(finish(w, p, b, h, big_h, true, note, search.trace));
        }
    };
    let big_h = search.grow(steps, h, big_h);
    let note = "thin: step approach".to_string();
    let b = search.width(steps);
    Ok(finish(w, p, b, h, big_h, true, note, search.trace))
}

/// Width steps, h and H of a search, mm.
type Fit = (u32, f64, f64);

/// The search for a wall's sizes, with its trace.
struct Search<'a> {
    w: &'a WallDimensions,
    p: &'a SizingParameters,
    trace: Vec<Step>,
}

impl Search<'_> {
    /// The deflection at (B, h, H), logged with why it was tried, mm.
    fn log(&mut self, b: f64, h: f64, big_h: f64, action: &str) -> f64 {
        let d = deflection(self.w, self.p, b, h, big_h);
        self.trace.push(Step {
            b,
            h,
            big_h,
            deflection_mm: d,
            action: action.to_string(),
        });
        d
    }

    /// B after `steps` width steps, mm.
    fn width(&self, steps: u32) -> f64 {
        self.p.finishing_width_mm + f64::from(steps) * self.p.width_step()
    }

    /// A height down to whole cuts (one at least), mm.
    fn round_height(&self, v: f64) -> f64 {
        let cut = self.p.cut_height_mm;
        (((v + SAME_LENGTH_MM) / cut).floor() * cut).max(cut)
    }

    /// From the rules of thumb, h one cut less (H reset) while too much,
    /// then B one step wider: (steps, h, H) within the limit, or with the
    /// note why none is.
    fn fit(&mut self, mut steps: u32) -> Result<Fit, (Fit, String)> {
        let (w, p) = (self.w, self.p);
        let cut = p.cut_height_mm;
        let initial_h = self
            .round_height(f64::from(p.initial_cuts) * cut)
            .min(self.round_height(w.height));
        // H: the initial whole multiple of h, within the wall.
        let reset_big = |h: f64| (p.initial_height_ratio.floor() * h).min(w.height).max(h);
        let mut h = initial_h;
        let mut big_h = reset_big(h);
        let mut d = self.log(self.width(steps), h, big_h, "initial: rules of thumb");
        while d > p.allowed_deflection_mm {
            if h > cut + SAME_LENGTH_MM {
                h = self.round_height(h - cut);
                big_h = reset_big(h);
                d = self.log(
                    self.width(steps),
                    h,
                    big_h,
                    "too much deflection: h one cut less, H reset",
                );
            } else if steps < MAX_WIDTH_STEPS {
                steps += 1;
                d = self.log(
                    self.width(steps),
                    h,
                    big_h,
                    "h at one cut and still too much: B one step wider",
                );
            } else {
                let note = format!(
                    "no sizes keep the deflection within {} mm (B up to {:.1} mm): the wall needs other measures",
                    p.allowed_deflection_mm,
                    self.width(steps)
                );
                return Err(((steps, h, big_h), note));
            }
        }
        Ok((steps, h, big_h))
    }

    /// Grow H by h within the limit, the wall and the tall-wall ratio.
    fn grow(&mut self, steps: u32, h: f64, mut big_h: f64) -> f64 {
        let (w, p) = (self.w, self.p);
        let b = self.width(steps);
        let cap = if w.height > 4.0 * h + SAME_LENGTH_MM {
            p.tall_wall_max_ratio * h
        } else {
            f64::INFINITY
        };
        while big_h + h <= w.height + SAME_LENGTH_MM && big_h + h <= cap + SAME_LENGTH_MM {
            let next = self.log(b, h, big_h + h, "within the limit: H one h more");
            if next > p.allowed_deflection_mm {
                self.trace.last_mut().expect("just logged").action =
                    "H one h more exceeds the limit: keep the last".to_string();
                break;
            }
            big_h += h;
        }
        if big_h + h <= w.height + SAME_LENGTH_MM && big_h + h > cap + SAME_LENGTH_MM {
            let d = deflection(w, p, b, h, big_h + h);
            self.trace.push(Step {
                b,
                h,
                big_h: big_h + h,
                deflection_mm: d,
                action: format!(
                    "H one h more passes the ratio cap {}·h of walls higher than 4·h (Fokker test 10): keep the last",
                    p.tall_wall_max_ratio
                ),
            });
        }
        big_h
    }
}

#[allow(clippy::too_many_arguments)]
fn finish(
    w: &WallDimensions,
    p: &SizingParameters,
    b: f64,
    h: f64,
    big_h: f64,
    thin: bool,
    note: String,
    trace: Vec<Step>,
) -> Sizes {
    Sizes {
        b,
        h,
        big_h,
        deflection_mm: if thin {
            deflection(w, p, b, h, big_h)
        } else {
            deflection(w, p, 0.0, p.cut_height_mm, p.cut_height_mm)
        },
        milling: p.milling,
        thin,
        note,
        wall: *w,
        parameters: p.clone(),
        trace,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wall(length: f64, thickness: f64, height: f64) -> WallDimensions {
        WallDimensions {
            length,
            thickness,
            height,
        }
    }

    #[test]
    fn a_uniform_cantilever_matches_the_textbook() {
        // All sections the same thickness: δ_top = F L³ / 3EI, plus the
        // slope F L² / 2EI times the zone.
        let mut p = SizingParameters::defaults(Milling::Peripheral);
        p.cut_height_mm = 1.0;
        let w = wall(100.0, 2.0, 10.0);
        let d = deflection(&w, &p, 0.0, 1.0, 1.0);
        let ei = p.youngs_modulus_n_mm2 * 40.0 * 8.0 / 12.0;
        let want = p.force_n * 1000.0 / (3.0 * ei) + p.force_n * 100.0 / (2.0 * ei) * 9.0;
        assert!((d - want).abs() < 1e-12 * want.max(1.0), "{d} {want}");
    }
}
