//! The set-ups of a report as text (the operations' and the plan's
//! sheets say them alike): why they were proposed, and what none reaches.

use std::fmt::Write;

/// The set-ups proposed: the first set-up's candidates, then why each
/// was taken.
pub(crate) fn proposal_text(s: &mut String, p: &thinwall_setups::proposal::Proposal) {
    let _ = writeln!(
        s,
        "set-ups proposed: {} (first among {} ups the part's faces face, the most material reachable first):",
        p.ups.len(),
        p.candidates.len()
    );
    for (k, c) in p.candidates.iter().enumerate() {
        let u = c.up;
        let what = match (c.reachable_mm3, c.out_of_reach_mm3, &c.refused) {
            (Some(r), Some(l), _) => {
                format!("reaches {r:.1} mm³, leaves {l:.1} mm³ under the part")
            }
            (_, _, Some(why)) => format!("refused: {why}"),
            _ => String::new(),
        };
        let _ = writeln!(
            s,
            "  {} up ({:.3}, {:.3}, {:.3}), {:.0} mm² facing it: {what}",
            if k == 0 { "*" } else { " " },
            u[0],
            u[1],
            u[2],
            c.facing_area_mm2
        );
    }
    for why in &p.why {
        let _ = writeln!(s, "  - {why}");
    }
}

/// What no set-up reaches.
pub(crate) fn residue_text(s: &mut String, r: &thinwall_setups::turn::Residue) {
    let how = match r.judged {
        thinwall_setups::turn::Judged::Exact => "exactly",
        thinwall_setups::turn::Judged::AtPoints => "judged at points inside the blocks",
    };
    if r.blocks == 0 {
        let _ = writeln!(
            s,
            "\nno set-up leaves material the others do not reach ({how})"
        );
        return;
    }
    let faces: Vec<String> = r.faces.iter().map(|f| format!("#{f}")).collect();
    let _ = writeln!(
        s,
        "\nresidue: {:.1} mm³ in {} block(s) that no set-up reaches ({how}), round faces {}",
        r.volume_mm3,
        r.blocks,
        faces.join(", ")
    );
}
