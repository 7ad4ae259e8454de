//! The two-phase sequence algorithm (Popma §6.2.1). Phase 1 finds, for
//! every ordered pair of features, every rule that applies and the
//! constraint it would give. Phase 2 takes those candidates in priority
//! order, across pairs, and enforces one only if it causes no conflict, no
//! redundancy and no cycle with the constraints already in force; every
//! decision is kept with its reason.
//!
//! Constraints live on a graph of *groups*: features made simultaneous are
//! one group (petgraph's union-find), `before` constraints are edges
//! between groups. `a` precedes `b` when a path leads from `a`'s group to
//! `b`'s.

use crate::rules::{
    ConnectionCondition, GoesFirst, HeightCondition, OrientationCondition, Relation, Rule, RuleSet,
};
use crate::scene::{Fact, Scene};
use petgraph::algo::{astar, has_path_connecting, toposort};
use petgraph::graph::{DiGraph, NodeIndex};
use petgraph::unionfind::UnionFind;
use serde::Serialize;
use std::collections::BTreeMap;
use thinwall_analysis::{FeatureId, StiffnessKind};

/// A constraint in force.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Constraint {
    /// With `relation` `before`: machined first.
    pub before: FeatureId,
    pub after: FeatureId,
    pub relation: Relation,
    pub rule: String,
}

/// Why a candidate was not enforced.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Rejection {
    /// It contradicts constraints in force.
    Conflict,
    /// Constraints in force already imply it.
    Redundant,
    /// It would close a cycle of `before` constraints.
    Cycle,
}

/// A candidate not enforced, with its reason.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Rejected {
    pub before: FeatureId,
    pub after: FeatureId,
    pub relation: Relation,
    pub rule: String,
    pub reason: Rejection,
    /// The constraints in force behind the reason, in chain order.
    pub because: Vec<Constraint>,
    /// The same in words.
    pub explanation: String,
}

/// The outcome of both phases.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Sequence {
    /// Enforced constraints, in the order they were enforced.
    pub constraints: Vec<Constraint>,
    pub rejected: Vec<Rejected>,
    /// A valid order: groups of features that may be machined together,
    /// level by level.
    pub order: Vec<Vec<FeatureId>>,
    #[serde(skip)]
    ids: Vec<FeatureId>,
    #[serde(skip)]
    groups: Vec<usize>,
    /// `before` constraints by feature index (first, second, constraint).
    #[serde(skip)]
    befores: Vec<(usize, usize, usize)>,
}

/// A candidate of phase 1.
struct Candidate<'r> {
    rule: &'r Rule,
    first: usize,
    second: usize,
}

/// Run both phases on the scene with the rules.
pub fn sequence(scene: &Scene, rules: &RuleSet) -> Sequence {
    let ids: Vec<FeatureId> = scene.facts.iter().map(|f| f.id).collect();
    let candidates = phase_one(scene, rules);
    let mut state = State::new(ids.len());
    let mut rejected = Vec::new();
    for c in candidates {
        let constraint = Constraint {
            before: ids[c.first],
            after: ids[c.second],
            relation: c.rule.relation,
            rule: c.rule.name.clone(),
        };
        match state.check(c.first, c.second, c.rule.relation) {
            Ok(()) => state.enforce(c.first, c.second, constraint),
            Err((reason, chain)) => {
                let because: Vec<Constraint> = chain
                    .iter()
                    .map(|&k| state.constraints[k].1.clone())
                    .collect();
                rejected.push(Rejected {
                    explanation: explain(&constraint, reason, &because),
                    before: constraint.before,
                    after: constraint.after,
                    relation: constraint.relation,
                    rule: constraint.rule,
                    reason,
                    because,
                });
            }
        }
    }
    let order = state.levels(&ids);
    let groups = state.reps();
    let befores = state.befores().collect();
    Sequence {
        constraints: state.constraints.into_iter().map(|c| c.1).collect(),
        rejected,
        order,
        ids,
        groups,
        befores,
    }
}

/// Phase 1: every applicable rule of every ordered pair, highest priority
/// first, then by the pair's ids (a fixed order whatever the face order).
fn phase_one<'r>(scene: &Scene, rules: &'r RuleSet) -> Vec<Candidate<'r>> {
    let mut out = Vec::new();
    for rule in &rules.rules {
        let mut found: Vec<Candidate> = Vec::new();
        for (i, a) in scene.facts.iter().enumerate() {
            for (j, b) in scene.facts.iter().enumerate() {
                if i == j || !applies(rule, a, b, scene) {
                    continue;
                }
                let twin = found.iter().any(|c| c.first == j && c.second == i);
                if rule.relation == Relation::Simultaneous && twin {
                    continue;
                }
                let (first, second) = match (rule.relation, rule.goes_first) {
                    (Relation::Before, GoesFirst::Second) => (j, i),
                    _ => (i, j),
                };
                found.push(Candidate {
                    rule,
                    first,
                    second,
                });
            }
        }
        found.sort_by_key(|c| (scene.facts[c.first].id, scene.facts[c.second].id));
        out.extend(found);
    }
    out
}

/// Whether `rule` applies with `a` as its first and `b` as its second.
fn applies(rule: &Rule, a: &Fact, b: &Fact, scene: &Scene) -> bool {
    if !rule.first.contains(&a.kind) || !rule.second.contains(&b.kind) {
        return false;
    }
    let on = |x: &Fact, y: &Fact| scene.base.get(&x.id) == Some(&y.id);
    let crossing = scene.crossings.contains(&(a.id, b.id));
    let connected = match rule.connection {
        ConnectionCondition::Any => true,
        ConnectionCondition::FirstOnSecond => on(a, b),
        ConnectionCondition::SecondOnFirst => on(b, a),
        ConnectionCondition::Crossing => crossing,
        ConnectionCondition::None => !(on(a, b) || on(b, a) || crossing),
    };
    let tol = rule.height_tolerance_mm;
    let height = match rule.height {
        HeightCondition::Any => true,
        HeightCondition::Higher => a.top > b.top + tol,
        HeightCondition::Lower => a.top < b.top - tol,
        HeightCondition::Level => (a.top - b.top).abs() <= tol,
    };
    if !(connected && height) {
        return false;
    }
    if rule.orientation == OrientationCondition::Any {
        return true;
    }
    if orientation(a, b, rule.orientation_tolerance_deg) != Some(rule.orientation) {
        return false;
    }
    rule.max_in_row.is_none_or(|max| {
        let alike = scene
            .facts
            .iter()
            .filter(|r| r.kind == StiffnessKind::Rib && on(r, b))
            .filter(|r| orientation(r, b, rule.orientation_tolerance_deg) == Some(rule.orientation))
            .count();
        alike <= max
    })
}

/// How rib `a` runs on wall `b`: along `b`'s height within `tol` degrees,
/// vertical; square to it within `tol`, horizontal; none between, or when
/// `b` is a web (lying flat, its height is no direction of the set-up).
fn orientation(a: &Fact, b: &Fact, tol: f64) -> Option<OrientationCondition> {
    if b.kind == StiffnessKind::Web {
        return None;
    }
    let (l, h) = (a.length_direction?, b.height_direction?);
    let angle = l.dot(&h).abs().min(1.0).acos().to_degrees();
    if angle <= tol {
        Some(OrientationCondition::Vertical)
    } else if angle >= 90.0 - tol {
        Some(OrientationCondition::Horizontal)
    } else {
        None
    }
}

/// The constraints in force and the groups they make.
struct State {
    n: usize,
    groups: UnionFind<usize>,
    /// (first, second) feature indices and the constraint.
    constraints: Vec<((usize, usize), Constraint)>,
}

impl State {
    fn new(n: usize) -> Self {
        Self {
            n,
            groups: UnionFind::new(n),
            constraints: Vec::new(),
        }
    }

    /// Each feature's group (its representative).
    fn reps(&self) -> Vec<usize> {
        (0..self.n).map(|i| self.groups.find(i)).collect()
    }

    /// The `before` constraints: first, second, constraint index.
    fn befores(&self) -> impl Iterator<Item = (usize, usize, usize)> + '_ {
        self.constraints
            .iter()
            .enumerate()
            .filter(|(_, (_, c))| c.relation == Relation::Before)
            .map(|(k, ((a, b), _))| (*a, *b, k))
    }

    fn graph(&self) -> GroupGraph {
        GroupGraph::new(&self.reps(), self.befores())
    }

    /// The simultaneous constraints holding `a`'s group together.
    fn together(&self, a: usize) -> Vec<usize> {
        let r = self.groups.find(a);
        self.constraints
            .iter()
            .enumerate()
            .filter(|(_, ((x, _), c))| {
                c.relation == Relation::Simultaneous && self.groups.find(*x) == r
            })
            .map(|(k, _)| k)
            .collect()
    }

    /// Whether enforcing `first relation second` is sound; if not, why and
    /// through which constraints.
    fn check(&self, a: usize, b: usize, relation: Relation) -> Result<(), (Rejection, Vec<usize>)> {
        let (ra, rb) = (self.groups.find(a), self.groups.find(b));
        if ra == rb {
            let reason = match relation {
                Relation::Before => Rejection::Conflict,
                Relation::Simultaneous => Rejection::Redundant,
            };
            return Err((reason, self.together(a)));
        }
        let g = self.graph();
        match relation {
            Relation::Before => {
                if let Some(chain) = g.chain(ra, rb) {
                    return Err((Rejection::Redundant, chain));
                }
                match g.chain(rb, ra) {
                    Some(chain) => Err((Rejection::Cycle, chain)),
                    None => Ok(()),
                }
            }
            Relation::Simultaneous => match g.chain(ra, rb).or_else(|| g.chain(rb, ra)) {
                Some(chain) => Err((Rejection::Conflict, chain)),
                None => Ok(()),
            },
        }
    }

    fn enforce(&mut self, a: usize, b: usize, c: Constraint) {
        if c.relation == Relation::Simultaneous {
            self.groups.union(a, b);
        }
        self.constraints.push(((a, b), c));
    }

    /// Groups level by level: a group's level is one more than the highest
    /// level of the groups that must precede it.
    fn levels(&self, ids: &[FeatureId]) -> Vec<Vec<FeatureId>> {
        let GroupGraph { g, node } = self.graph();
        let sorted = toposort(&g, None).expect("phase 2 never closes a cycle");
        let mut level: BTreeMap<NodeIndex, usize> = BTreeMap::new();
        for &v in &sorted {
            let l = g
                .neighbors_directed(v, petgraph::Direction::Incoming)
                .map(|u| level[&u] + 1)
                .max()
                .unwrap_or(0);
            level.insert(v, l);
        }
        let depth = level.values().copied().max().map_or(0, |m| m + 1);
        let mut out = vec![Vec::new(); depth];
        for (i, id) in ids.iter().enumerate() {
            out[level[&node[&self.groups.find(i)]]].push(*id);
        }
        for l in &mut out {
            l.sort();
        }
        out
    }
}

/// Groups of simultaneous features as nodes (by representative), `before`
/// constraints between them as edges weighted by the constraint's index.
struct GroupGraph {
    g: DiGraph<usize, usize>,
    node: BTreeMap<usize, NodeIndex>,
}

impl GroupGraph {
    /// `reps[i]` is feature `i`'s group; `befores` are (first, second,
    /// constraint index) by feature.
    fn new(reps: &[usize], befores: impl Iterator<Item = (usize, usize, usize)>) -> Self {
        let mut g = DiGraph::new();
        let mut node = BTreeMap::new();
        for &r in reps {
            node.entry(r).or_insert_with(|| g.add_node(r));
        }
        for (a, b, k) in befores {
            g.add_edge(node[&reps[a]], node[&reps[b]], k);
        }
        Self { g, node }
    }

    /// The constraints along a path from group `a` to group `b`, if any.
    fn chain(&self, a: usize, b: usize) -> Option<Vec<usize>> {
        let (from, to) = (self.node[&a], self.node[&b]);
        if from == to || !has_path_connecting(&self.g, from, to, None) {
            return None;
        }
        let (_, path) = astar(&self.g, from, |x| x == to, |_| 1, |_| 0)?;
        Some(
            path.windows(2)
                .filter_map(|w| self.g.find_edge(w[0], w[1]).map(|e| self.g[e]))
                .collect(),
        )
    }
}

/// The nodes a breadth-first search from `start` reaches, `start` too.
fn reachable<G>(g: G, start: G::NodeId) -> Vec<G::NodeId>
where
    G: petgraph::visit::IntoNeighbors + petgraph::visit::Visitable,
{
    let mut bfs = petgraph::visit::Bfs::new(g, start);
    let mut out = Vec::new();
    while let Some(v) = bfs.next(g) {
        out.push(v);
    }
    out
}

/// A constraint in words.
pub fn describe(c: &Constraint) -> String {
    match c.relation {
        Relation::Before => format!("{} before {} ({})", c.before, c.after, c.rule),
        Relation::Simultaneous => format!("{} with {} ({})", c.before, c.after, c.rule),
    }
}

fn explain(c: &Constraint, reason: Rejection, because: &[Constraint]) -> String {
    let chain: Vec<String> = because.iter().map(describe).collect();
    let chain = chain.join(", ");
    match (reason, c.relation) {
        (Rejection::Conflict, Relation::Before) => format!(
            "{} cannot go before {}: they are machined together by {chain}",
            c.before, c.after
        ),
        (Rejection::Conflict, Relation::Simultaneous) => format!(
            "{} cannot go with {}: one must precede the other by {chain}",
            c.before, c.after
        ),
        (Rejection::Redundant, Relation::Before) => {
            format!("{} already precedes {} through {chain}", c.before, c.after)
        }
        (Rejection::Redundant, Relation::Simultaneous) => {
            format!("{} is already with {} through {chain}", c.before, c.after)
        }
        (Rejection::Cycle, _) => format!(
            "{} before {} would close a cycle with {chain}",
            c.before, c.after
        ),
    }
}

impl Sequence {
    fn index(&self, id: FeatureId) -> Option<usize> {
        self.ids.iter().position(|&x| x == id)
    }

    /// Features machined together with `id` (its group, without it).
    pub fn simultaneous(&self, id: FeatureId) -> Vec<FeatureId> {
        let Some(i) = self.index(id) else {
            return vec![];
        };
        (0..self.ids.len())
            .filter(|&j| j != i && self.groups[j] == self.groups[i])
            .map(|j| self.ids[j])
            .collect()
    }

    /// Features that must precede `id`: directly (a constraint names
    /// them, or their group) or, with `indirect`, through any chain.
    pub fn predecessors(&self, id: FeatureId, indirect: bool) -> Vec<FeatureId> {
        self.related(id, indirect, true)
    }

    /// Features that must follow `id` (as [`Sequence::predecessors`]).
    pub fn successors(&self, id: FeatureId, indirect: bool) -> Vec<FeatureId> {
        self.related(id, indirect, false)
    }

    fn related(&self, id: FeatureId, indirect: bool, before: bool) -> Vec<FeatureId> {
        let Some(i) = self.index(id) else {
            return vec![];
        };
        let GroupGraph { g, node } = GroupGraph::new(&self.groups, self.befores.iter().copied());
        let start = node[&self.groups[i]];
        let direction = if before {
            petgraph::Direction::Incoming
        } else {
            petgraph::Direction::Outgoing
        };
        let nodes: Vec<NodeIndex> = match (indirect, before) {
            (true, true) => reachable(petgraph::visit::Reversed(&g), start),
            (true, false) => reachable(&g, start),
            (false, _) => g.neighbors_directed(start, direction).collect(),
        };
        let reached: Vec<usize> = nodes
            .into_iter()
            .filter(|&v| v != start)
            .map(|v| g[v])
            .collect();
        let mut out: Vec<FeatureId> = (0..self.ids.len())
            .filter(|&k| reached.contains(&self.groups[k]))
            .map(|k| self.ids[k])
            .collect();
        out.sort();
        out
    }
}
