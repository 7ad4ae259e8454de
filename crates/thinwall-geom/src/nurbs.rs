//! Rational B-splines (NURBS): evaluation with first derivatives and point
//! inversion on surfaces (Piegl & Tiller, *The NURBS Book*, A2.1–A2.3, A4.x).
//!
//! Control points are stored homogeneous (`[w·x, w·y, w·z, w]`). Degrees up
//! to [`MAX_DEGREE`] are supported (STEP allows 1–25).

use crate::{Point3, Vector3};
use serde::{Deserialize, Serialize};

/// The highest degree we evaluate.
pub const MAX_DEGREE: usize = 25;
const M: usize = MAX_DEGREE + 1;

/// A NURBS curve.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NurbsCurve {
    pub degree: usize,
    pub knots: Vec<f64>,
    /// Homogeneous control points `[w·x, w·y, w·z, w]`.
    pub control: Vec<[f64; 4]>,
}

/// A NURBS surface; `control[i][j]` is indexed `[u][v]`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct NurbsSurface {
    pub degree_u: usize,
    pub degree_v: usize,
    pub knots_u: Vec<f64>,
    pub knots_v: Vec<f64>,
    pub control: Vec<Vec<[f64; 4]>>,
}

/// Why a NURBS definition was refused.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NurbsError {
    #[error("degree {0} outside 1..={MAX_DEGREE}")]
    Degree(usize),
    #[error("{found} knots where {expected} are needed")]
    KnotCount { expected: usize, found: usize },
    #[error("knots decrease")]
    NotIncreasing,
    #[error("a weight is not positive and finite")]
    BadWeight,
    #[error("no control points")]
    Empty,
}

impl NurbsError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            NurbsError::Degree(_) => "nurbs_degree",
            NurbsError::KnotCount { .. } => "nurbs_knot_count",
            NurbsError::NotIncreasing => "nurbs_knots_decrease",
            NurbsError::BadWeight => "nurbs_weight",
            NurbsError::Empty => "nurbs_empty",
        }
    }
}

fn check_knots(degree: usize, n_ctrl: usize, knots: &[f64]) -> Result<(), NurbsError> {
    if degree == 0 || degree > MAX_DEGREE {
        return Err(NurbsError::Degree(degree));
    }
    if n_ctrl == 0 {
        return Err(NurbsError::Empty);
    }
    if knots.len() != n_ctrl + degree + 1 {
        return Err(NurbsError::KnotCount {
            expected: n_ctrl + degree + 1,
            found: knots.len(),
        });
    }
    let increasing = knots
        .windows(2)
        .all(|w| w[1].partial_cmp(&w[0]).is_some_and(|o| o.is_ge()));
    if !increasing || knots[degree] >= knots[n_ctrl] {
        return Err(NurbsError::NotIncreasing);
    }
    Ok(())
}

fn homogeneous(p: [f64; 3], w: f64) -> Result<[f64; 4], NurbsError> {
    if !(w > 0.0 && w.is_finite()) || p.iter().any(|c| !c.is_finite()) {
        return Err(NurbsError::BadWeight);
    }
    Ok([p[0] * w, p[1] * w, p[2] * w, w])
}

/// The knot span index containing `u` (clamped into the domain).
fn find_span(n_ctrl: usize, p: usize, u: f64, knots: &[f64]) -> usize {
    if u >= knots[n_ctrl] {
        // Last non-empty span.
        let mut s = n_ctrl - 1;
        while s > p && knots[s] >= knots[s + 1] {
            s -= 1;
        }
        return s;
    }
    if u <= knots[p] {
        let mut s = p;
        while s + 1 < n_ctrl && knots[s] >= knots[s + 1] {
            s += 1;
        }
        return s;
    }
    let (mut lo, mut hi) = (p, n_ctrl);
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if u < knots[mid] {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    lo
}

/// Scratch size for the common degrees (< 8): small arrays keep evaluation
/// cheap; higher degrees use [`M`].
const SMALL: usize = 8;
/// Basis arrays for cubic and lower degrees (most CAD surfaces).
const CUBIC: usize = 4;

/// Non-zero basis functions at `u` and their first derivatives (`p < N`).
fn basis_with_derivative<const N: usize>(
    span: usize,
    u: f64,
    p: usize,
    knots: &[f64],
) -> ([f64; N], [f64; N]) {
    let mut ndu = [[0.0f64; N]; N];
    let mut left = [0.0f64; N];
    let mut right = [0.0f64; N];
    ndu[0][0] = 1.0;
    for j in 1..=p {
        left[j] = u - knots[span + 1 - j];
        right[j] = knots[span + j] - u;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = if ndu[j][r] != 0.0 {
                ndu[r][j - 1] / ndu[j][r]
            } else {
                0.0
            };
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    let mut n = [0.0f64; N];
    let mut dn = [0.0f64; N];
    for r in 0..=p {
        n[r] = ndu[r][p];
        let mut d = 0.0;
        if r >= 1 && ndu[p][r - 1] != 0.0 {
            d += ndu[r - 1][p - 1] / ndu[p][r - 1];
        }
        if r < p && ndu[p][r] != 0.0 {
            d -= ndu[r][p - 1] / ndu[p][r];
        }
        dn[r] = p as f64 * d;
    }
    (n, dn)
}

fn project(a: [f64; 4]) -> Point3 {
    Point3::new(a[0] / a[3], a[1] / a[3], a[2] / a[3])
}

fn rational_derivative(a: [f64; 4], da: [f64; 4], c: &Point3) -> Vector3 {
    Vector3::new(
        (da[0] - da[3] * c.x) / a[3],
        (da[1] - da[3] * c.y) / a[3],
        (da[2] - da[3] * c.z) / a[3],
    )
}

impl NurbsCurve {
    /// A curve from Cartesian control points and weights, validated.
    pub fn new(
        degree: usize,
        knots: Vec<f64>,
        points: &[[f64; 3]],
        weights: &[f64],
    ) -> Result<Self, NurbsError> {
        check_knots(degree, points.len(), &knots)?;
        if weights.len() != points.len() {
            return Err(NurbsError::BadWeight);
        }
        let control = points
            .iter()
            .zip(weights)
            .map(|(p, w)| homogeneous(*p, *w))
            .collect::<Result<_, _>>()?;
        Ok(Self {
            degree,
            knots,
            control,
        })
    }

    /// The parameter domain.
    pub fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.control.len()])
    }

    /// The distinct knot values inside the domain, domain ends included:
    /// the pieces on which the curve is one rational polynomial.
    pub fn spans(&self) -> Vec<(f64, f64)> {
        let (a, b) = self.domain();
        let mut breaks: Vec<f64> = vec![a];
        for &k in &self.knots {
            if k > *breaks.last().unwrap() && k < b {
                breaks.push(k);
            }
        }
        breaks.push(b);
        breaks.windows(2).map(|w| (w[0], w[1])).collect()
    }

    /// Whether every weight is the same (a polynomial curve).
    pub fn is_polynomial(&self) -> bool {
        let w0 = self.control[0][3];
        self.control.iter().all(|c| (c[3] - w0).abs() <= 1e-14 * w0)
    }

    /// The point at `t` and the derivative there.
    pub fn eval(&self, t: f64) -> (Point3, Vector3) {
        if self.degree < CUBIC {
            self.eval_n::<CUBIC>(t)
        } else if self.degree < SMALL {
            self.eval_n::<SMALL>(t)
        } else {
            self.eval_n::<M>(t)
        }
    }

    fn eval_n<const N: usize>(&self, t: f64) -> (Point3, Vector3) {
        let p = self.degree;
        let span = find_span(self.control.len(), p, t, &self.knots);
        let (n, dn) = basis_with_derivative::<N>(span, t, p, &self.knots);
        let mut a = [0.0; 4];
        let mut da = [0.0; 4];
        for r in 0..=p {
            let c = self.control[span - p + r];
            for k in 0..4 {
                a[k] += n[r] * c[k];
                da[k] += dn[r] * c[k];
            }
        }
        let pt = project(a);
        (pt, rational_derivative(a, da, &pt))
    }

    /// The point at `t`.
    pub fn point(&self, t: f64) -> Point3 {
        self.eval(t).0
    }

    /// The same curve run the other way (parameter `t` ↦ `a + b − t`).
    pub fn reversed(&self) -> Self {
        let (a, b) = (self.knots[0], self.knots[self.knots.len() - 1]);
        Self {
            degree: self.degree,
            knots: self.knots.iter().rev().map(|k| a + b - k).collect(),
            control: self.control.iter().rev().copied().collect(),
        }
    }

    /// Move every control point.
    pub fn map_points(&mut self, f: impl Fn(Point3) -> Point3) {
        for c in &mut self.control {
            let w = c[3];
            let q = f(Point3::new(c[0] / w, c[1] / w, c[2] / w));
            *c = [q.x * w, q.y * w, q.z * w, w];
        }
    }
}

impl NurbsCurve {
    /// The exact arc of the ellipse `C + a cos θ·x + b sin θ·y` (a circle
    /// when `a = b`) from `start` sweeping `sweep` radians (negative:
    /// clockwise about `frame.z`), as rational quadratic pieces of at most
    /// 90° (Piegl & Tiller A7.1). `None` for a zero sweep or bad axes.
    pub fn ellipse_arc(
        frame: &crate::Frame,
        a: f64,
        b: f64,
        start: f64,
        sweep: f64,
    ) -> Option<Self> {
        if !(a > 0.0 && b > 0.0 && sweep.is_finite() && sweep.abs() > 1e-12) {
            return None;
        }
        let pieces = (sweep.abs() / std::f64::consts::FRAC_PI_2 - 1e-9)
            .ceil()
            .max(1.0) as usize;
        let step = sweep / pieces as f64;
        let w_mid = (0.5 * step).cos();
        let at = |theta: f64, scale: f64| {
            let p = frame.origin
                + frame.x * (a * scale * theta.cos())
                + frame.y * (b * scale * theta.sin());
            [p.x, p.y, p.z]
        };
        let mut points = vec![at(start, 1.0)];
        let mut weights = vec![1.0];
        let mut knots = vec![0.0; 3];
        for i in 0..pieces {
            let t0 = start + step * i as f64;
            points.push(at(t0 + 0.5 * step, 1.0 / w_mid));
            weights.push(w_mid);
            points.push(at(t0 + step, 1.0));
            weights.push(1.0);
            let k = (i + 1) as f64 / pieces as f64;
            knots.push(k);
            knots.push(k);
        }
        knots.push(1.0);
        Self::new(2, knots, &points, &weights).ok()
    }
}

/// Point, ∂/∂u and ∂/∂v of a surface.
pub struct SurfacePoint {
    pub point: Point3,
    pub du: Vector3,
    pub dv: Vector3,
}

impl NurbsSurface {
    /// A surface from a `[u][v]` grid of Cartesian points and weights, validated.
    pub fn new(
        degree_u: usize,
        degree_v: usize,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        points: &[Vec<[f64; 3]>],
        weights: &[Vec<f64>],
    ) -> Result<Self, NurbsError> {
        let nv = points.first().map_or(0, Vec::len);
        check_knots(degree_u, points.len(), &knots_u)?;
        check_knots(degree_v, nv, &knots_v)?;
        if weights.len() != points.len() {
            return Err(NurbsError::BadWeight);
        }
        let mut control = Vec::with_capacity(points.len());
        for (row, wrow) in points.iter().zip(weights) {
            if row.len() != nv || wrow.len() != nv {
                return Err(NurbsError::KnotCount {
                    expected: nv,
                    found: row.len(),
                });
            }
            control.push(
                row.iter()
                    .zip(wrow)
                    .map(|(p, w)| homogeneous(*p, *w))
                    .collect::<Result<Vec<_>, _>>()?,
            );
        }
        Ok(Self {
            degree_u,
            degree_v,
            knots_u,
            knots_v,
            control,
        })
    }

    pub fn n_u(&self) -> usize {
        self.control.len()
    }

    pub fn n_v(&self) -> usize {
        self.control[0].len()
    }

    /// The parameter domain `((u0, u1), (v0, v1))`.
    pub fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (
            (self.knots_u[self.degree_u], self.knots_u[self.n_u()]),
            (self.knots_v[self.degree_v], self.knots_v[self.n_v()]),
        )
    }

    /// Point and first partial derivatives at `(u, v)`.
    pub fn eval(&self, u: f64, v: f64) -> SurfacePoint {
        let degree = self.degree_u.max(self.degree_v);
        if degree < CUBIC {
            self.eval_n::<CUBIC>(u, v)
        } else if degree < SMALL {
            self.eval_n::<SMALL>(u, v)
        } else {
            self.eval_n::<M>(u, v)
        }
    }

    fn eval_n<const N: usize>(&self, u: f64, v: f64) -> SurfacePoint {
        let (pu, pv) = (self.degree_u, self.degree_v);
        let su = find_span(self.n_u(), pu, u, &self.knots_u);
        let sv = find_span(self.n_v(), pv, v, &self.knots_v);
        let (nu, dnu) = basis_with_derivative::<N>(su, u, pu, &self.knots_u);
        let (nv, dnv) = basis_with_derivative::<N>(sv, v, pv, &self.knots_v);
        let mut a = [0.0; 4];
        let mut au = [0.0; 4];
        let mut av = [0.0; 4];
        for i in 0..=pu {
            let row = &self.control[su - pu + i];
            let mut t = [0.0; 4];
            let mut tv = [0.0; 4];
            for j in 0..=pv {
                let c = row[sv - pv + j];
                for k in 0..4 {
                    t[k] += nv[j] * c[k];
                    tv[k] += dnv[j] * c[k];
                }
            }
            for k in 0..4 {
                a[k] += nu[i] * t[k];
                au[k] += dnu[i] * t[k];
                av[k] += nu[i] * tv[k];
            }
        }
        let point = project(a);
        SurfacePoint {
            point,
            du: rational_derivative(a, au, &point),
            dv: rational_derivative(a, av, &point),
        }
    }

    /// Gauss–Newton from `(u, v)` towards the foot of `p`, clamped to the
    /// domain. Returns `(u, v, distance, stationary)`; `stationary` when the
    /// residual is orthogonal to both tangents (a true foot point).
    fn newton(&self, p: &Point3, mut u: f64, mut v: f64) -> (f64, f64, f64, bool) {
        let ((u0, u1), (v0, v1)) = self.domain();
        let mut stationary = false;
        for _ in 0..30 {
            let s = self.eval(u, v);
            let r = s.point - p;
            let a11 = s.du.dot(&s.du);
            let a12 = s.du.dot(&s.dv);
            let a22 = s.dv.dot(&s.dv);
            let b1 = -s.du.dot(&r);
            let b2 = -s.dv.dot(&r);
            let rn = r.norm();
            if b1.abs() <= 1e-10 * a11.sqrt() * rn.max(1e-12) + 1e-15
                && b2.abs() <= 1e-10 * a22.sqrt() * rn.max(1e-12) + 1e-15
            {
                stationary = true;
                break;
            }
            let det = a11 * a22 - a12 * a12;
            if det.abs() < 1e-300 {
                break;
            }
            let du = (b1 * a22 - b2 * a12) / det;
            let dv = (a11 * b2 - a12 * b1) / det;
            let nu = (u + du).clamp(u0, u1);
            let nv = (v + dv).clamp(v0, v1);
            let step = (nu - u).abs() / (u1 - u0) + (nv - v).abs() / (v1 - v0);
            u = nu;
            v = nv;
            if step < 1e-13 {
                stationary = true;
                break;
            }
        }
        let d = (self.eval(u, v).point - p).norm();
        (u, v, d, stationary)
    }

    /// Parameters of the point of the surface nearest to `p`, starting from
    /// `hint` when given (a neighbouring point's parameters), else from the
    /// nearest of a coarse grid. Returns `(u, v, distance)`.
    pub fn invert(&self, p: &Point3, hint: Option<(f64, f64)>) -> (f64, f64, f64) {
        let ((u0, u1), (v0, v1)) = self.domain();
        if let Some((hu, hv)) = hint {
            let (u, v, d, stationary) = self.newton(p, hu, hv);
            let moved = (u - hu).abs() / (u1 - u0) + (v - hv).abs() / (v1 - v0);
            if stationary && moved < 0.25 {
                return (u, v, d);
            }
        }
        // Coarse grid: a few samples per control point in each direction.
        let gu = (self.n_u() * 2).clamp(6, 32);
        let gv = (self.n_v() * 2).clamp(6, 32);
        let mut best = (u0, v0, f64::INFINITY);
        for i in 0..=gu {
            let u = u0 + (u1 - u0) * i as f64 / gu as f64;
            for j in 0..=gv {
                let v = v0 + (v1 - v0) * j as f64 / gv as f64;
                let d = (self.eval(u, v).point - p).norm_squared();
                if d < best.2 {
                    best = (u, v, d);
                }
            }
        }
        let (u, v, d, _) = self.newton(p, best.0, best.1);
        (u, v, d)
    }

    /// Move every control point.
    /// The control points (Cartesian): with positive weights the surface
    /// lies in their convex hull.
    pub fn control_points(&self) -> impl Iterator<Item = Point3> + '_ {
        self.control
            .iter()
            .flatten()
            .map(|c| Point3::new(c[0] / c[3], c[1] / c[3], c[2] / c[3]))
    }

    pub fn map_points(&mut self, f: impl Fn(Point3) -> Point3) {
        for row in &mut self.control {
            for c in row {
                let w = c[3];
                let q = f(Point3::new(c[0] / w, c[1] / w, c[2] / w));
                *c = [q.x * w, q.y * w, q.z * w, w];
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quarter circle of radius 2 as a rational quadratic.
    fn quarter_circle() -> NurbsCurve {
        let w = std::f64::consts::FRAC_1_SQRT_2;
        NurbsCurve::new(
            2,
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            &[[2.0, 0.0, 0.0], [2.0, 2.0, 0.0], [0.0, 2.0, 0.0]],
            &[1.0, w, 1.0],
        )
        .unwrap()
    }

    #[test]
    fn rational_circle_stays_on_circle_with_tangent_derivative() {
        let c = quarter_circle();
        for i in 0..=20 {
            let t = i as f64 / 20.0;
            let (p, d) = c.eval(t);
            assert!((p.coords.norm() - 2.0).abs() < 1e-12, "t={t}");
            assert!(p.coords.dot(&d).abs() < 1e-10, "tangent at t={t}");
        }
        // Finite-difference check of the derivative.
        let h = 1e-6;
        let fd = (c.point(0.3 + h) - c.point(0.3 - h)) / (2.0 * h);
        assert!((fd - c.eval(0.3).1).norm() < 1e-6);
    }

    #[test]
    fn ellipse_arcs_are_exact_and_run_the_right_way() {
        let f = crate::Frame::world();
        let full = NurbsCurve::ellipse_arc(&f, 3.0, 3.0, 0.0, std::f64::consts::TAU).unwrap();
        assert_eq!(full.spans().len(), 4);
        for i in 0..=40 {
            let (t0, t1) = full.domain();
            let p = full.point(t0 + (t1 - t0) * i as f64 / 40.0);
            assert!((p.coords.norm() - 3.0).abs() < 1e-12);
        }
        // Clockwise quarter from +x ends at -y.
        let cw = NurbsCurve::ellipse_arc(&f, 2.0, 1.0, 0.0, -std::f64::consts::FRAC_PI_2).unwrap();
        let end = cw.point(cw.domain().1);
        assert!((end - Point3::new(0.0, -1.0, 0.0)).norm() < 1e-12);
        let mid = cw.point(0.5);
        assert!(mid.y < 0.0 && ((mid.x / 2.0).powi(2) + mid.y.powi(2) - 1.0).abs() < 1e-12);
        assert!(NurbsCurve::ellipse_arc(&f, 1.0, 1.0, 0.0, 0.0).is_none());
    }

    #[test]
    fn reversed_curve_runs_backwards() {
        let c = quarter_circle();
        let r = c.reversed();
        assert_eq!(r.domain(), c.domain());
        for i in 0..=10 {
            let t = i as f64 / 10.0;
            assert!((r.point(t) - c.point(1.0 - t)).norm() < 1e-12);
        }
    }

    #[test]
    fn high_degree_curves_evaluate_like_low_degree_ones() {
        // A straight line as a degree-9 Bézier (evenly spaced control
        // points) takes the large-scratch path.
        let pts: Vec<[f64; 3]> = (0..10).map(|i| [i as f64, 2.0 * i as f64, 0.0]).collect();
        let mut knots = vec![0.0; 10];
        knots.extend(vec![1.0; 10]);
        let c = NurbsCurve::new(9, knots, &pts, &[1.0; 10]).unwrap();
        let (p, d) = c.eval(0.25);
        assert!((p - Point3::new(2.25, 4.5, 0.0)).norm() < 1e-12);
        assert!((d - Vector3::new(9.0, 18.0, 0.0)).norm() < 1e-9);
    }

    #[test]
    fn invalid_definitions_are_refused() {
        assert_eq!(
            NurbsCurve::new(0, vec![0.0, 1.0], &[[0.0; 3]], &[1.0]),
            Err(NurbsError::Degree(0))
        );
        assert!(matches!(
            NurbsCurve::new(1, vec![0.0, 1.0], &[[0.0; 3], [1.0; 3]], &[1.0, 1.0]),
            Err(NurbsError::KnotCount { .. })
        ));
        assert_eq!(
            NurbsCurve::new(
                1,
                vec![0.0, 0.0, 1.0, 1.0],
                &[[0.0; 3], [1.0; 3]],
                &[1.0, -1.0]
            ),
            Err(NurbsError::BadWeight)
        );
        assert_eq!(
            NurbsCurve::new(
                1,
                vec![1.0, 1.0, 0.0, 0.0],
                &[[0.0; 3], [1.0; 3]],
                &[1.0, 1.0]
            ),
            Err(NurbsError::NotIncreasing)
        );
    }

    #[test]
    fn bilinear_patch_evaluates_and_inverts() {
        let s = NurbsSurface::new(
            1,
            2,
            vec![0.0, 0.0, 1.0, 1.0],
            vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
            &[
                vec![[0.0, 0.0, 0.0], [0.0, 1.0, 1.0], [0.0, 2.0, 0.0]],
                vec![[3.0, 0.0, 0.0], [3.0, 1.0, 1.0], [3.0, 2.0, 0.0]],
            ],
            &[vec![1.0; 3], vec![1.0; 3]],
        )
        .unwrap();
        let sp = s.eval(0.5, 0.5);
        assert!((sp.point - Point3::new(1.5, 1.0, 0.5)).norm() < 1e-12);
        assert!((sp.du - Vector3::new(3.0, 0.0, 0.0)).norm() < 1e-12);
        let target = s.eval(0.3, 0.8).point;
        let (u, v, d) = s.invert(&target, None);
        assert!(d < 1e-10 && (u - 0.3).abs() < 1e-8 && (v - 0.8).abs() < 1e-8);
    }

    #[test]
    fn spans_list_distinct_knot_intervals() {
        let c = NurbsCurve::new(
            1,
            vec![0.0, 0.0, 0.5, 0.5, 1.0, 1.0],
            &[[0.0; 3], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [2.0, 1.0, 0.0]],
            &[1.0; 4],
        )
        .unwrap();
        assert_eq!(c.spans(), vec![(0.0, 0.5), (0.5, 1.0)]);
        assert!(c.is_polynomial());
    }
}
