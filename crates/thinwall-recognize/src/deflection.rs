//! Static cantilever deflection of a wall under the milling force
//! (Popma 4.1.2, 6.1.1): `δ = F·h³ / (3·E·I)`, `I = L_eff·t³/12`,
//! `L_eff = min(L, k·h)`.

use crate::config::Thinness;

/// Deflection in mm of a wall of thickness `t`, height `h`, length `l` (mm).
pub fn deflection_mm(t: f64, h: f64, l: f64, m: &Thinness) -> f64 {
    let l_eff = l.min(m.effective_length_factor * h);
    let inertia = l_eff * t.powi(3) / 12.0;
    if inertia <= 0.0 {
        return f64::INFINITY;
    }
    m.force_n * h.powi(3) / (3.0 * m.youngs_modulus_n_mm2 * inertia)
}

/// The linear (small-deflection) cantilever model holds while the
/// deflection stays under this fraction of the height.
pub const SMALL_DEFLECTION_RATIO: f64 = 0.1;
/// Bending dominates, and the beam model holds, from this h/t up; a
/// squatter wall also shears, which the model leaves out.
pub const MIN_BEAM_SLENDERNESS: f64 = 5.0;

/// Where a wall's figures leave the model's validity, in a planner's words
/// (`None` while they are inside it).
pub fn validity_note(t: f64, h: f64, deflection: f64) -> Option<String> {
    if deflection > SMALL_DEFLECTION_RATIO * h {
        return Some(format!(
            "δ = {deflection:.3} mm is over {:.0} % of h = {h:.2} mm: outside the linear cantilever model (the wall is thin either way; treat δ as a ranking, not a size)",
            100.0 * SMALL_DEFLECTION_RATIO
        ));
    }
    let slenderness = if t > 0.0 { h / t } else { f64::INFINITY };
    if slenderness < MIN_BEAM_SLENDERNESS {
        return Some(format!(
            "h/t = {slenderness:.1} is under {MIN_BEAM_SLENDERNESS}: a short wall also shears, which the bending model leaves out (δ is a lower bound)"
        ));
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn notes_when_the_model_stops_holding() {
        // CTC 03's web: 1.91 thick, 374 high, δ 231 mm.
        assert!(validity_note(1.91, 374.65, 231.0)
            .unwrap()
            .contains("outside the linear"));
        assert!(validity_note(20.0, 70.0, 0.005).unwrap().contains("shears"));
        assert!(validity_note(1.0, 48.0, 0.5).is_none());
    }

    #[test]
    fn domain_examples() {
        let m = Thinness::default();
        // DOMAIN.md: a 120 × 1 × 48 mm rib deflects about 10 mm.
        let thin = deflection_mm(1.0, 48.0, 120.0, &m);
        assert!((thin - 10.53).abs() < 0.05, "{thin}");
        // … a 20 mm wall of the same height about 0.001 mm.
        let thick = deflection_mm(20.0, 48.0, 120.0, &m);
        assert!(thick < 0.01 && thick > 0.0005, "{thick}");
    }
}
