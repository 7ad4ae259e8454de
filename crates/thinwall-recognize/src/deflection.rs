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

#[cfg(test)]
mod tests {
    use super::*;

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
