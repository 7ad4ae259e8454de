//! The file's reference graph, checked before anything recursive runs.
//!
//! step-io resolves references recursively (units through their conversion
//! factors, surface curves through their 3-D curve, products through their
//! usages) and does not guard against cycles: a `CONVERSION_BASED_UNIT`
//! whose measure names the unit itself overflows its stack, which no
//! `catch_unwind` can stop. So the reader first scans the `#id = …;`
//! statements of the text for the references between them and refuses a
//! file whose references go round in a circle, naming the entities, before
//! step-io is asked anything. The same scan finds cycles in the product
//! structure (`NEXT_ASSEMBLY_USAGE_OCCURRENCE` relating → related), rooted or
//! not, which are not reference cycles of the text.
//!
//! The scan is one pass over the bytes (strings and comments skipped) into a
//! compact adjacency list; cycles are petgraph's strongly connected
//! components.

use petgraph::algo::tarjan_scc;
use petgraph::graph::{DiGraph, NodeIndex};
use petgraph::graphmap::DiGraphMap;
use std::collections::HashMap;

/// Most entities a cycle's message lists.
const NAMED_IN_A_CYCLE: usize = 12;

/// Parts of the entity names whose references step-io follows recursively
/// (units through their measures; curves, surfaces, placements, topology and
/// mapped representations). A cycle elsewhere — a PMI dimension whose
/// datum feature is itself, as NIST STC 07 has — is legal and harmless, so
/// only cycles through these entities are refused.
const FOLLOWED: &[&str] = &[
    "UNIT",
    "CURVE",
    "SURFACE",
    "PLACEMENT",
    "TRANSFORMATION",
    "MAPPED_ITEM",
    "REPRESENTATION_MAP",
    "POINT",
    "DIRECTION",
    "VECTOR",
    "LINE",
    "CIRCLE",
    "ELLIPSE",
    "EDGE",
    "VERTEX",
    "LOOP",
    "FACE",
    "SHELL",
    "BREP",
    "SOLID",
];

/// The statements of the DATA section: each one's id, its entity names (one,
/// or the partial entities of a complex instance), and the ids it refers to,
/// in order.
#[derive(Debug, Default)]
pub struct References {
    ids: Vec<u64>,
    keywords: Vec<Vec<String>>,
    /// `refs[starts[i]..starts[i + 1]]` are statement i's references.
    starts: Vec<usize>,
    refs: Vec<u64>,
}

impl References {
    /// Scan `bytes` (strings and comments skipped).
    pub fn scan(bytes: &[u8]) -> Self {
        let mut out = References {
            starts: vec![0],
            ..Self::default()
        };
        let mut scanner = Scanner { bytes, i: 0 };
        while let Some(id) = scanner.next_statement() {
            let (keyword, refs) = scanner.body();
            out.ids.push(id);
            out.keywords.push(keyword);
            out.refs.extend(refs);
            out.starts.push(out.refs.len());
        }
        out
    }

    /// References to entities the file does not define: `(referrer,
    /// missing)`, in file order.
    pub fn dangling(&self) -> Vec<(u64, u64)> {
        let defined: std::collections::HashSet<u64> = self.ids.iter().copied().collect();
        (0..self.ids.len())
            .flat_map(|i| {
                self.refs_of(i)
                    .iter()
                    .filter(|r| !defined.contains(r))
                    .map(move |&r| (self.ids[i], r))
            })
            .collect()
    }

    /// The id of the last statement.
    pub fn last_id(&self) -> Option<u64> {
        self.ids.last().copied()
    }

    /// Every statement in file order: its position, id, entity names and
    /// references.
    pub fn statements(&self) -> impl Iterator<Item = (usize, u64, &[String], &[u64])> + '_ {
        (0..self.ids.len()).map(|i| (i, self.ids[i], &self.keywords[i][..], self.refs_of(i)))
    }

    fn refs_of(&self, i: usize) -> &[u64] {
        &self.refs[self.starts[i]..self.starts[i + 1]]
    }

    /// The entities of one reference cycle among the entities step-io
    /// follows (ascending, at most a dozen), if there is one.
    pub fn cycle(&self) -> Option<Vec<u64>> {
        // Each distinct keyword is matched once (they were matched again
        // for every reference to a statement).
        let mut known: HashMap<&str, bool> = HashMap::new();
        let followed: Vec<bool> = self
            .keywords
            .iter()
            .map(|ks| {
                ks.iter().any(|k| {
                    *known
                        .entry(k.as_str())
                        .or_insert_with(|| FOLLOWED.iter().any(|f| k.contains(f)))
                })
            })
            .collect();
        let index: HashMap<u64, usize> = self
            .ids
            .iter()
            .enumerate()
            .map(|(i, id)| (*id, i))
            .collect();
        // A node per statement (its id the weight): no hashing per edge.
        let mut g: DiGraph<u64, ()> = DiGraph::with_capacity(self.ids.len(), self.refs.len());
        for &id in &self.ids {
            g.add_node(id);
        }
        for i in (0..self.ids.len()).filter(|&i| followed[i]) {
            for &r in self.refs_of(i) {
                if let Some(&j) = index.get(&r).filter(|&&j| followed[j]) {
                    g.add_edge(NodeIndex::new(i), NodeIndex::new(j), ());
                }
            }
        }
        tarjan_scc(&g)
            .into_iter()
            .filter(|c| c.len() > 1 || g.contains_edge(c[0], c[0]))
            .map(|c| c.into_iter().map(|n| g[n]).collect())
            .map(named)
            .min_by_key(|c| c[0])
    }

    /// The entities of a cycle in the product structure: the product
    /// definitions that contain themselves and the usages that make them do
    /// so (ascending, at most a dozen).
    pub fn assembly_cycle(&self) -> Option<Vec<u64>> {
        let mut g: DiGraphMap<u64, ()> = DiGraphMap::new();
        let mut usage_of: HashMap<(u64, u64), u64> = HashMap::new();
        for (i, keyword) in self.keywords.iter().enumerate() {
            if !keyword
                .iter()
                .any(|k| k == "NEXT_ASSEMBLY_USAGE_OCCURRENCE")
            {
                continue;
            }
            if let [relating, related, ..] = self.refs_of(i) {
                g.add_edge(*relating, *related, ());
                usage_of.entry((*relating, *related)).or_insert(self.ids[i]);
            }
        }
        let mut members = first_cycle(&g)?;
        let usages: Vec<u64> = usage_of
            .iter()
            .filter(|((a, b), _)| members.contains(a) && members.contains(b))
            .map(|(_, u)| *u)
            .collect();
        members.extend(usages);
        members.sort_unstable();
        members.truncate(NAMED_IN_A_CYCLE);
        Some(members)
    }
}

/// The smallest-id strongly connected component that is a cycle (more than
/// one node, or a node referring to itself).
fn first_cycle(g: &DiGraphMap<u64, ()>) -> Option<Vec<u64>> {
    tarjan_scc(g)
        .into_iter()
        .filter(|c| c.len() > 1 || g.contains_edge(c[0], c[0]))
        .map(named)
        .min_by_key(|c| c[0])
}

/// A cycle's ids as named: ascending, at most [`NAMED_IN_A_CYCLE`].
fn named(mut c: Vec<u64>) -> Vec<u64> {
    c.sort_unstable();
    c.truncate(NAMED_IN_A_CYCLE);
    c
}

/// `#1, #2 → #1` for messages.
pub fn list(ids: &[u64]) -> String {
    ids.iter()
        .map(|i| format!("#{i}"))
        .collect::<Vec<_>>()
        .join(", ")
}

struct Scanner<'b> {
    bytes: &'b [u8],
    i: usize,
}

impl Scanner<'_> {
    fn peek(&self) -> Option<u8> {
        self.bytes.get(self.i).copied()
    }

    /// Past a string or comment starting at `i`, if one does.
    fn skip_quoted(&mut self) -> bool {
        let b = self.bytes;
        match b[self.i] {
            b'\'' => {
                self.i += 1;
                while self.i < b.len() {
                    if b[self.i] == b'\'' {
                        if b.get(self.i + 1) == Some(&b'\'') {
                            self.i += 2;
                            continue;
                        }
                        break;
                    }
                    self.i += 1;
                }
                self.i += 1;
                true
            }
            b'/' if b.get(self.i + 1) == Some(&b'*') => {
                self.i += 2;
                while self.i + 1 < b.len() && !(b[self.i] == b'*' && b[self.i + 1] == b'/') {
                    self.i += 1;
                }
                self.i += 2;
                true
            }
            _ => false,
        }
    }

    fn number(&mut self) -> Option<u64> {
        let start = self.i;
        let mut v: u64 = 0;
        while let Some(d) = self.peek().filter(u8::is_ascii_digit) {
            v = v.saturating_mul(10).saturating_add(u64::from(d - b'0'));
            self.i += 1;
        }
        (self.i > start).then_some(v)
    }

    fn skip_space(&mut self) {
        while self.peek().is_some_and(|c| c.is_ascii_whitespace()) {
            self.i += 1;
        }
    }

    /// The id of the next `#id =` at a statement start, leaving `i` after `=`.
    fn next_statement(&mut self) -> Option<u64> {
        let mut at_start = true;
        while self.i < self.bytes.len() {
            if self.skip_quoted() {
                at_start = false;
                continue;
            }
            match self.bytes[self.i] {
                b';' => {
                    at_start = true;
                    self.i += 1;
                }
                b'#' if at_start => {
                    self.i += 1;
                    let id = self.number();
                    self.skip_space();
                    if let (Some(id), Some(b'=')) = (id, self.peek()) {
                        self.i += 1;
                        return Some(id);
                    }
                    at_start = false;
                }
                c if c.is_ascii_whitespace() => self.i += 1,
                _ => {
                    at_start = false;
                    self.i += 1;
                }
            }
        }
        None
    }

    /// The statement's entity names (the one before its parameters, or
    /// those of a complex instance's partial entities) and its references,
    /// leaving `i` after its `;`.
    fn body(&mut self) -> (Vec<String>, Vec<u64>) {
        let mut names = Vec::new();
        let mut refs = Vec::new();
        let (mut depth, mut complex, mut seen_any) = (0usize, false, false);
        while self.i < self.bytes.len() {
            if self.skip_quoted() {
                continue;
            }
            let c = self.bytes[self.i];
            self.i += 1;
            match c {
                b';' => break,
                b'#' => refs.extend(self.number()),
                b'(' => {
                    complex |= depth == 0 && !seen_any;
                    seen_any = true;
                    depth += 1;
                }
                b')' => depth = depth.saturating_sub(1),
                c if c.is_ascii_alphabetic() || c == b'_' => {
                    let mut word = String::from(c.to_ascii_uppercase() as char);
                    while let Some(k) = self
                        .peek()
                        .filter(|k| k.is_ascii_alphanumeric() || *k == b'_')
                    {
                        word.push(k.to_ascii_uppercase() as char);
                        self.i += 1;
                    }
                    let name_level = if complex { 1 } else { 0 };
                    if depth == name_level && (complex || names.is_empty()) {
                        names.push(word);
                    }
                    seen_any = true;
                }
                _ => {}
            }
        }
        (names, refs)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scan(s: &str) -> References {
        References::scan(s.as_bytes())
    }

    #[test]
    fn statements_keywords_and_references_skip_strings_and_comments() {
        let r = scan(
            "DATA;\n#1 = FOO('#9;#8=X(',#2,(#3,#4));\n#2 = ( BAR(/* #8 */ #1) BAZ(#3) );\nENDSEC;",
        );
        assert_eq!(r.ids, vec![1, 2]);
        assert_eq!(r.keywords, vec![vec!["FOO"], vec!["BAR", "BAZ"]]);
        assert_eq!(r.refs_of(0), &[2, 3, 4]);
        assert_eq!(r.refs_of(1), &[1, 3]);
    }

    #[test]
    fn dangling_references_name_referrer_and_missing_entity() {
        let text = "DATA;\n#1 = FOO('#9 in a string',#2,(#3,#4));\n#2 = BAR(/* #8 */ #1);\n#3 = BAZ();\nENDSEC;";
        assert_eq!(scan(text).dangling(), vec![(1, 4)]);
    }

    #[test]
    fn a_unit_measured_in_itself_is_a_cycle_and_a_chain_is_not() {
        let looped = "#5 = ( CONVERSION_BASED_UNIT('MM',#6) LENGTH_UNIT() NAMED_UNIT(#7) );\n\
                      #6 = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.),#5);\n#7 = DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);";
        assert_eq!(scan(looped).cycle(), Some(vec![5, 6]));
        let chain = "#5 = ( CONVERSION_BASED_UNIT('INCH',#6) LENGTH_UNIT() NAMED_UNIT(#7) );\n\
                     #6 = LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),#8);\n#7 = DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.);\n\
                     #8 = ( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );";
        assert_eq!(scan(chain).cycle(), None);
        assert_eq!(
            scan("#3 = SURFACE_CURVE('',#3,(),.PCURVE_S1.);").cycle(),
            Some(vec![3])
        );
        // Of two cycles, the one with the smallest id is named.
        let two = "#10 = SURFACE_CURVE('',#11,(),.PCURVE_S1.);\n#11 = SURFACE_CURVE('',#10,(),.PCURVE_S1.);\n\
                   #4 = SURFACE_CURVE('',#3,(),.PCURVE_S1.);\n#3 = SURFACE_CURVE('',#4,(),.PCURVE_S1.);";
        assert_eq!(scan(two).cycle(), Some(vec![3, 4]));
        // A PMI dimension whose datum feature is itself (NIST STC 07) is legal.
        let pmi = "#9 = DIMENSIONAL_SIZE_WITH_DATUM_FEATURE('a','b',#11,.T.,#9,'diameter');";
        assert_eq!(scan(pmi).cycle(), None);
    }

    #[test]
    fn rootless_and_rooted_assembly_cycles_name_definitions_and_usages() {
        let rootless =
            "#1 = PRODUCT_DEFINITION('a','',#9,#9);\n#2 = PRODUCT_DEFINITION('b','',#9,#9);\n\
                        #3 = NEXT_ASSEMBLY_USAGE_OCCURRENCE('1','','',#1,#2,$);\n\
                        #4 = NEXT_ASSEMBLY_USAGE_OCCURRENCE('2','','',#2,#1,$);";
        assert_eq!(scan(rootless).assembly_cycle(), Some(vec![1, 2, 3, 4]));
        let tree =
            "#1 = PRODUCT_DEFINITION('a','',#9,#9);\n#2 = PRODUCT_DEFINITION('b','',#9,#9);\n\
                    #3 = NEXT_ASSEMBLY_USAGE_OCCURRENCE('1','','',#1,#2,$);\n\
                    #4 = NEXT_ASSEMBLY_USAGE_OCCURRENCE('2','','',#1,#2,$);";
        assert_eq!(scan(tree).assembly_cycle(), None);
        let itself = "#1 = NEXT_ASSEMBLY_USAGE_OCCURRENCE('1','','',#7,#7,$);";
        assert_eq!(scan(itself).assembly_cycle(), Some(vec![1, 7]));
    }
}
