//! Can the tool reach a side of a wall in the set-up? Judged here from the
//! side's tool access direction (its outward normal) against the machine's
//! tool axis. Obstruction by other material (`thinwall_access::reach`) is
//! judged above this layer; the pipeline adds its `fraction`, `blocked_by`
//! and reason to the verdict.

use serde::{Deserialize, Serialize};
use thinwall_analysis::Machine;
use thinwall_geom::Vector3;

/// Angle within which a side counts as facing straight up or as vertical.
const ANGLE_TOL_DEG: f64 = thinwall_geom::tolerance::FEATURE_PARALLEL_DEG;

/// The verdict for one side of a wall.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SideAccess {
    /// The side's outward normal (unit).
    pub direction: [f64; 3],
    pub reachable: bool,
    /// Why, in a planner's words.
    pub reason: String,
    /// The share of the side the tool reaches with material in the way
    /// (the pipeline's reach judgement; absent when not judged).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fraction: Option<f64>,
    /// The tool judged with, mm.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub tool_diameter: Option<f64>,
    /// Features in the way, the worst first.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub blocked_by: Vec<thinwall_analysis::FeatureId>,
}

/// Judge a side with access direction `d` for a machine whose tool axis is `up`.
pub fn side_access(d: [f64; 3], up: &Vector3, machine: &Machine) -> SideAccess {
    let dv = Vector3::new(d[0], d[1], d[2])
        .try_normalize(1e-12)
        .unwrap_or_else(Vector3::z);
    let c = dv.dot(up).clamp(-1.0, 1.0);
    // Elevation of the direction above the machine's horizontal plane.
    let elevation = c.asin().to_degrees();
    let (reachable, reason) = if elevation >= 90.0 - ANGLE_TOL_DEG {
        (true, "faces up: face milling with the tool end".to_string())
    } else if elevation.abs() <= ANGLE_TOL_DEG {
        (
            true,
            "vertical: peripheral milling with the tool side".to_string(),
        )
    } else if elevation > 0.0 {
        (
            true,
            format!("inclined {elevation:.1}° upwards: reachable from above"),
        )
    } else if elevation <= -90.0 + ANGLE_TOL_DEG {
        (
            false,
            "faces down (towards the table): needs another set-up".to_string(),
        )
    } else {
        let under = -elevation;
        match machine {
            Machine::ThreeAxis => (
                false,
                format!("undercut by {under:.1}°: a 3-axis machine cannot reach it"),
            ),
            Machine::FiveAxis { tilt_limit_deg } if under <= *tilt_limit_deg => (
                true,
                format!("undercut by {under:.1}°: within the {tilt_limit_deg}° tilt limit"),
            ),
            Machine::FiveAxis { tilt_limit_deg } => (
                false,
                format!("undercut by {under:.1}°: beyond the {tilt_limit_deg}° tilt limit"),
            ),
        }
    };
    SideAccess {
        direction: [dv.x, dv.y, dv.z],
        reachable,
        reason,
        fraction: None,
        tool_diameter: None,
        blocked_by: Vec::new(),
    }
}

/// Judge a curved side whose outward normal sweeps through `dirs` (samples
/// along its arc, in order): the verdict at its worst direction (the
/// lowest elevation), with the sweep in the reason.
pub fn swept_side_access(dirs: &[[f64; 3]], up: &Vector3, machine: &Machine) -> Option<SideAccess> {
    let verdicts: Vec<SideAccess> = dirs.iter().map(|&d| side_access(d, up, machine)).collect();
    let elevation = |v: &SideAccess| Vector3::from(v.direction).dot(up);
    let (lo, hi) = verdicts
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            let e = elevation(v).clamp(-1.0, 1.0).asin().to_degrees();
            (lo.min(e), hi.max(e))
        });
    let worst = verdicts.into_iter().min_by(|a, b| {
        a.reachable
            .cmp(&b.reachable)
            .then(elevation(a).total_cmp(&elevation(b)))
    })?;
    let first = Vector3::from(dirs[0]);
    let last = Vector3::from(dirs[dirs.len() - 1]);
    let sweep = first.angle(&last).to_degrees();
    Some(SideAccess {
        reason: format!(
            "curved: the normal sweeps {sweep:.1}°, elevation {lo:.1}° to {hi:.1}°; at its worst {}",
            worst.reason
        ),
        ..worst
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn verdicts_follow_the_tool_axis() {
        let up = Vector3::z();
        let three = Machine::ThreeAxis;
        assert!(side_access([0.0, 0.0, 1.0], &up, &three).reachable);
        let side = side_access([1.0, 0.0, 0.0], &up, &three);
        assert!(side.reachable && side.reason.contains("vertical"));
        let down = side_access([0.0, 0.0, -1.0], &up, &three);
        assert!(!down.reachable && down.reason.contains("another set-up"));
        let s = 10f64.to_radians().sin();
        let c = 10f64.to_radians().cos();
        assert!(!side_access([c, 0.0, -s], &up, &three).reachable);
        let five = Machine::FiveAxis {
            tilt_limit_deg: 15.0,
        };
        assert!(side_access([c, 0.0, -s], &up, &five).reachable);
        let steep = Machine::FiveAxis {
            tilt_limit_deg: 5.0,
        };
        assert!(!side_access([c, 0.0, -s], &up, &steep).reachable);
        assert!(side_access([c, 0.0, s], &up, &three)
            .reason
            .contains("upwards"));
    }

    #[test]
    fn a_curved_side_is_judged_at_its_worst_direction() {
        let up = Vector3::z();
        // A side whose normal sweeps from 30° up, through horizontal, to
        // 20° down: a 3-axis machine cannot reach all of it.
        let dirs: Vec<[f64; 3]> = [30.0f64, 0.0, -20.0]
            .iter()
            .map(|e| {
                let e = e.to_radians();
                [e.cos(), 0.0, e.sin()]
            })
            .collect();
        let v = swept_side_access(&dirs, &up, &Machine::ThreeAxis).unwrap();
        assert!(!v.reachable);
        assert!(v.reason.contains("sweeps 50.0°"), "{}", v.reason);
        assert!(v.reason.contains("undercut by 20.0°"), "{}", v.reason);
        let five = Machine::FiveAxis {
            tilt_limit_deg: 30.0,
        };
        assert!(swept_side_access(&dirs, &up, &five).unwrap().reachable);
        // All above the horizon: reachable.
        let ok = swept_side_access(&dirs[..2], &up, &Machine::ThreeAxis).unwrap();
        assert!(ok.reachable, "{}", ok.reason);
    }
}
