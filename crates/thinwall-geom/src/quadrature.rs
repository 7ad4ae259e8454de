//! Gauss–Legendre quadrature on `[a, b]`.

use std::sync::OnceLock;

/// Nodes and weights of the `n`-point Gauss–Legendre rule on `[-1, 1]`,
/// computed once by Newton iteration on the Legendre polynomial.
fn rule(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n {
        // Chebyshev-like initial guess, then Newton.
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 1.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, 0.0);
            for j in 0..n {
                let p2 = p1;
                p1 = p0;
                p0 = ((2 * j + 1) as f64 * z * p1 - j as f64 * p2) / (j + 1) as f64;
            }
            dp = n as f64 * (z * p0 - p1) / (z * z - 1.0);
            let dz = p0 / dp;
            z -= dz;
            if dz.abs() < 1e-15 {
                break;
            }
        }
        x[i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
    (x, w)
}

/// The rules we use, cached.
fn cached(n: usize) -> &'static (Vec<f64>, Vec<f64>) {
    static R2: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    static R8: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    static R16: OnceLock<(Vec<f64>, Vec<f64>)> = OnceLock::new();
    match n {
        0..=2 => R2.get_or_init(|| rule(2)),
        3..=8 => R8.get_or_init(|| rule(8)),
        _ => R16.get_or_init(|| rule(16)),
    }
}

/// Calls `f(t, weight)` at the nodes of an `n`-point rule (n is rounded up
/// to 2, 8 or 16) mapped to `[a, b]`; the weights include the interval
/// scaling, so `Σ weight·g(t)` approximates `∫ₐᵇ g`.
pub fn for_each_node(a: f64, b: f64, n: usize, mut f: impl FnMut(f64, f64)) {
    let (x, w) = cached(n);
    let half = 0.5 * (b - a);
    let mid = 0.5 * (a + b);
    for (xi, wi) in x.iter().zip(w) {
        f(mid + half * xi, wi * half);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_polynomials_and_trig_exactly() {
        let mut s = 0.0;
        for_each_node(0.0, 2.0, 2, |t, w| s += w * t * t * t);
        assert!((s - 4.0).abs() < 1e-13);
        let mut s = 0.0;
        for_each_node(0.0, std::f64::consts::FRAC_PI_2, 16, |t, w| {
            s += w * t.cos()
        });
        assert!((s - 1.0).abs() < 1e-14);
        let mut s = 0.0;
        for_each_node(-1.0, 1.0, 8, |t, w| s += w * t.powi(14));
        assert!((s - 2.0 / 15.0).abs() < 1e-13);
    }
}
