//! A plan (`thinwall/plan/2`) as JSON and as text: the planner computes
//! it, this module only writes it.

use thinwall_plan::{features, sequence, Plan};

/// The removal and its features, in order, then per wall.
fn removal_text(plan: &Plan, s: &mut String) {
    use std::fmt::Write;
    let r = &plan.removal;
    if let Some(why) = &r.unavailable {
        let _ = writeln!(
            s,
            "removal plan: not available (removal.{}: {why})",
            why.code()
        );
        return;
    }
    let _ = writeln!(
        s,
        "removal: stock ({}) {:.1} mm³ − part {:.1} mm³ = {:.1} mm³ in {} machining features ({} cells)",
        r.stock,
        r.stock_volume_mm3,
        r.part_volume_mm3,
        r.removed_volume_mm3 + r.cleared_before_mm3,
        plan.machining_features.len(),
        r.cells
    );
    if r.cleared_before_mm3 > 0.0 {
        let _ = writeln!(
            s,
            "  {:.1} mm³ of it taken by the set-ups before; {:.1} mm³ taken in part before, cut again here",
            r.cleared_before_mm3, r.recut_mm3
        );
    }
    meshed_line(s, &r.meshed);
    for n in &r.notes {
        let _ = writeln!(s, "  note: {n}");
    }
    let by_id: std::collections::HashMap<&str, &features::RemovalFeature> = plan
        .machining_features
        .iter()
        .map(|f| (f.id.as_str(), f))
        .collect();
    let _ = writeln!(s, "machining features in order:");
    for (k, id) in plan.feature_sequence.order.iter().enumerate() {
        let Some(f) = by_id.get(id.as_str()) else {
            continue;
        };
        let owner = f.owner.map(|o| o.to_string()).unwrap_or_else(|| "-".into());
        let place = match (f.side, f.step) {
            (Some(side), Some(step)) => format!("side {} step {step}", side + 1),
            _ => String::new(),
        };
        let reach = match (f.reachable, f.access) {
            (true, _) => String::new(),
            (false, Some(d)) => format!(
                "  another set-up, from ({:.3}, {:.3}, {:.3})",
                d[0], d[1], d[2]
            ),
            (false, None) => "  another set-up".to_string(),
        };
        let _ = writeln!(
            s,
            "  {:>3}. {:<5}{:<12}{:<5} {:<16}{:>8.2} .. {:>8.2}  {:>12.1} mm³  {} faces{}",
            k + 1,
            f.id,
            f.size_class.name(),
            owner,
            place,
            f.z_range[0],
            f.z_range[1],
            f.volume_mm3,
            f.faces.len(),
            reach
        );
        for c in &f.changes {
            let _ = writeln!(s, "         {c}");
        }
    }
    let _ = writeln!(s, "per wall, in order:");
    for w in &plan.walls {
        let ids: Vec<&str> = plan
            .feature_sequence
            .order
            .iter()
            .filter(|id| {
                by_id
                    .get(id.as_str())
                    .is_some_and(|f| f.owner == Some(w.id))
            })
            .map(|id| id.as_str())
            .collect();
        if !ids.is_empty() {
            let _ = writeln!(s, "  {:<5}{}", w.id, ids.join(" "));
        }
    }
    if !plan.feature_sequence.dropped.is_empty() {
        let _ = writeln!(
            s,
            "relations dropped (they would contradict height or a step approach):"
        );
        for d in &plan.feature_sequence.dropped {
            let _ = writeln!(s, "  {} before {}: {}", d.before, d.after, d.why);
        }
    }
}

/// Pretty JSON.
pub fn to_json(plan: &Plan) -> String {
    serde_json::to_string_pretty(plan).expect("a plan serialises")
}

/// What the walls' sizes and the layers' words mean.
pub const SIZES_LEGEND: &str = "  (the step approach, Popma §4.1.1: the material beside a thin wall is taken in layers \
B_RF wide, large ones H_RF tall on one side and small ones h_RF tall on the other, alternately, so the wall \
stays supported below each cut; large layers go on the side facing up, or with more stiffness features \
standing on it; sides are numbered 1 and 2; a web is face milled and its figures are across its span)";

/// A table a planner can read: the order, the constraints, the
/// rejected candidates; over several set-ups, why they were proposed,
/// each set-up's table in turn and what none reaches.
pub fn to_text(plan: &Plan) -> String {
    use std::fmt::Write;
    if plan.then.is_empty() {
        return setup_text(plan);
    }
    let mut s = String::new();
    if let Some(p) = &plan.proposal {
        crate::setups::proposal_text(&mut s, p);
    }
    let n = 1 + plan.then.len();
    for (k, p) in std::iter::once(plan).chain(&plan.then).enumerate() {
        let u = p.up;
        let _ = writeln!(
            s,
            "\n== set-up {} of {n}: up ({:.3}, {:.3}, {:.3}) ==",
            k + 1,
            u[0],
            u[1],
            u[2]
        );
        s.push_str(&setup_text(p));
    }
    if let Some(r) = &plan.residue {
        crate::setups::residue_text(&mut s, r);
    }
    s
}

/// One set-up's table.
fn setup_text(plan: &Plan) -> String {
    use std::fmt::Write;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "{}: {} stiffness features, rules: {}",
        plan.file,
        plan.stiffness_features.len(),
        plan.rules
    );
    let _ = writeln!(s, "order ({} levels):", plan.order.len());
    for (i, level) in plan.order.iter().enumerate() {
        let names: Vec<String> = level.iter().map(|f| f.to_string()).collect();
        let _ = writeln!(s, "  {:>3}  {}", i + 1, names.join(" "));
    }
    let _ = writeln!(s, "sequence constraints: {}", plan.sequence.len());
    for c in &plan.sequence {
        let _ = writeln!(s, "  {}", sequence::describe(c));
    }
    let _ = writeln!(s, "thin walls: {}", plan.walls.len());
    for w in &plan.walls {
        let _ = writeln!(
            s,
            "  {:<5}{:<8}{:<11} B_RF {:>6.2}  h_RF {:>6.2}  H_RF {:>6.2}  deflection {:.4}  {}",
            w.id,
            w.kind,
            format!("{:?}", w.sizes.milling).to_lowercase(),
            w.sizes.b,
            w.sizes.h,
            w.sizes.big_h,
            w.sizes.deflection_mm,
            w.sizes.note
        );
    }
    if !plan.walls.is_empty() {
        let _ = writeln!(s, "{SIZES_LEGEND}");
    }
    if !plan.adaptations.is_empty() {
        let _ = writeln!(s, "adaptations (§4.1.3): {}", plan.adaptations.len());
        for a in &plan.adaptations {
            let _ = writeln!(
                s,
                "  {:<4} by {:<4} {:?}: {}",
                a.wall, a.by, a.rule, a.change
            );
        }
    }
    let _ = writeln!(s, "step-approach layers as designed: {}", plan.layers.len());
    for l in &plan.layers {
        let _ = writeln!(
            s,
            "  {:<5}{:<5} step {:>2}  side {}  {:<5}  {:>7.2} .. {:>7.2} above the foot  ({:.2} x {:.2} x {:.2})",
            l.id,
            l.owner,
            l.step,
            l.side + 1,
            format!("{:?}", l.size_class).to_lowercase(),
            l.from_foot[0],
            l.from_foot[1],
            l.length,
            l.width,
            l.height
        );
    }
    removal_text(plan, &mut s);
    for l in &plan.limits {
        let _ = writeln!(s, "not planned yet: {l}");
    }
    if !plan.supported_webs.is_empty() {
        let ids: Vec<String> = plan.supported_webs.iter().map(|f| f.to_string()).collect();
        let _ = writeln!(
            s,
            "supported webs: {} (material a later set-up takes is still under them: no step layers here)",
            ids.join(" ")
        );
    }
    let _ = writeln!(s, "rejected candidates: {}", plan.rejected.len());
    for r in &plan.rejected {
        let _ = writeln!(s, "  [{:?}] {}", r.reason, r.explanation);
    }
    s
}

/// The removal's meshed faces and the bound they imply, if any.
fn meshed_line(s: &mut String, m: &thinwall_plan::removal::pieces::Meshed) {
    use std::fmt::Write;
    if m.is_empty() {
        return;
    }
    let _ = writeln!(
        s,
        "  meshed: {}: the removal within ±{:.3} mm³ of the exact one",
        meshed_faces(m),
        m.volume_bound_mm3
    );
}

/// A removal's meshed faces in words: how many, as how many triangles,
/// within what deviation, over what area (the plan's and the operations'
/// sheets say it alike).
pub(crate) fn meshed_faces(m: &thinwall_plan::removal::pieces::Meshed) -> String {
    format!(
        "{} face(s) as {} triangles within {:.4} mm ({:.1} mm²)",
        m.faces.len(),
        m.triangles,
        m.deviation_mm,
        m.area_mm2
    )
}
