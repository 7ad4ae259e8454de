//! The order in which OpenCascade numbers the faces of the shape it reads
//! from a STEP file (`STEPControl_Reader` then `TopExp::MapShapes(shape,
//! TopAbs_FACE)`), so that a host built on it (FreeCAD, CadQuery,
//! build123d, pythonOCC, Analysis Situs) can find our faces among its own.
//!
//! OpenCascade transfers a part's shape representation and then the
//! representations related to it, each in the order of the statement that
//! links it (a `SHAPE_DEFINITION_REPRESENTATION`, a
//! `SHAPE_REPRESENTATION_RELATIONSHIP`) in the file; within one, the items
//! in their listed order; within a shell, its faces in order. A solid's and
//! a surface model's faces therefore follow the rank of the link that brings
//! in their representation, per product definition in the order the
//! assembly is walked. Checked against OpenCascade 7.9/8.0 on every shared
//! part and fixture by the Python package's tests (`python/tests`).

use crate::references::References;
use std::collections::{HashMap, HashSet};

/// The faces of one solid or surface model, as the reader placed them.
#[derive(Clone, Debug)]
pub struct Group {
    /// Which product definition visit (or later phase) placed it.
    pub visit: usize,
    /// The solid's or surface model's entity id.
    pub item: u64,
    /// Its faces: `first..first + count` of the part's faces for a body;
    /// `None` for a supplemental surface model (counted, not read).
    pub first: Option<usize>,
    pub count: usize,
}

/// Per face of the part (by index), its ordinal in OpenCascade's order.
pub fn ordinals(refs: &References, groups: &[Group], faces: usize) -> Vec<u32> {
    let items: Vec<u64> = groups.iter().map(|g| g.item).collect();
    let rank = link_ranks(refs, &items);
    let mut order: Vec<usize> = (0..groups.len()).collect();
    order.sort_by_key(|&i| {
        let g = &groups[i];
        (g.visit, rank.get(&g.item).copied().unwrap_or(usize::MAX), i)
    });
    let mut out = vec![0u32; faces];
    let mut next = 0u32;
    for i in order {
        let g = &groups[i];
        if let Some(first) = g.first {
            for (k, slot) in out[first..first + g.count].iter_mut().enumerate() {
                *slot = next + k as u32;
            }
        }
        next += g.count as u32;
    }
    out
}

/// Whether a statement's entity is a representation (not a relationship).
fn is_representation(keywords: &[String]) -> bool {
    keywords
        .iter()
        .any(|k| k.ends_with("REPRESENTATION") && k != "SHAPE_DEFINITION_REPRESENTATION")
}

/// Whether a statement links a representation into a part's shape.
fn is_link(keywords: &[String]) -> bool {
    keywords.iter().any(|k| {
        k == "SHAPE_DEFINITION_REPRESENTATION" || k.ends_with("REPRESENTATION_RELATIONSHIP")
    })
}

/// Per item, the file position of the earliest statement that links a
/// representation listing it. A representation nothing links (a saved
/// view's, NIST STC 07's `MBD_A`) is not transferred as the part's shape
/// and does not count; an item no linked representation lists has no
/// rank (it keeps the reader's order, after those ranked).
fn link_ranks(refs: &References, items: &[u64]) -> HashMap<u64, usize> {
    let wanted: HashSet<u64> = items.iter().copied().collect();
    // The representations listing each item.
    let mut reps_of: HashMap<u64, Vec<u64>> = HashMap::new();
    let mut reps: HashSet<u64> = HashSet::new();
    for (_, id, keywords, rs) in refs.statements() {
        if !is_representation(keywords) {
            continue;
        }
        for r in rs.iter().filter(|r| wanted.contains(r)) {
            reps_of.entry(*r).or_default().push(id);
            reps.insert(id);
        }
    }
    let mut linked: HashMap<u64, usize> = HashMap::new();
    for (pos, _, keywords, rs) in refs.statements() {
        if !is_link(keywords) {
            continue;
        }
        for r in rs.iter().filter(|r| reps.contains(r)) {
            linked.entry(*r).or_insert(pos);
        }
    }
    reps_of
        .into_iter()
        .map(|(item, reps)| {
            let rank = reps
                .iter()
                .filter_map(|r| linked.get(r).copied())
                .min()
                .unwrap_or(usize::MAX);
            (item, rank)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_follow_the_links_of_their_representations_per_visit() {
        // Surface model #5 in representation #6, linked by #7; solid #1 in
        // representation #2, linked by #8: the surface model's faces first.
        let text = "DATA;\n#1=MANIFOLD_SOLID_BREP('',#9);\n#2=ADVANCED_BREP_SHAPE_REPRESENTATION('',(#1),#3);\n\
            #5=SHELL_BASED_SURFACE_MODEL('',(#10));\n#6=MANIFOLD_SURFACE_SHAPE_REPRESENTATION('',(#5),#3);\n\
            #7=SHAPE_REPRESENTATION_RELATIONSHIP('','',#4,#6);\n#8=SHAPE_REPRESENTATION_RELATIONSHIP('','',#4,#2);\nENDSEC;";
        let refs = References::scan(text.as_bytes());
        let g = |visit, item, first, count| Group {
            visit,
            item,
            first,
            count,
        };
        let groups = [g(0, 1, Some(0), 3), g(0, 5, None, 2)];
        assert_eq!(ordinals(&refs, &groups, 3), vec![2, 3, 4]);
        // A later visit (an assembly's next instance) comes after, whatever
        // its rank.
        let groups = [g(1, 5, None, 2), g(0, 1, Some(0), 3), g(2, 1, Some(3), 3)];
        assert_eq!(ordinals(&refs, &groups, 6), vec![0, 1, 2, 5, 6, 7]);
    }
}
