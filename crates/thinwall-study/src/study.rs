//! The study of one part: per set-up, one analysis and the results
//! computed on it, each at most once.

use crate::memo::Memo;
use crate::{LoadedPart, StudyError};
use std::sync::Arc;
use std::time::{Duration, Instant};
use thinwall_analysis::{PartAnalysis, Setup};
use thinwall_pipeline::{Outcome, PipelineError, Request};
use thinwall_plan::{Plan, RuleSet};

/// A part under study. Cheap to make; costly pieces are built on first use
/// and kept for the study's life.
pub struct Study<'p> {
    loaded: &'p LoadedPart,
    parallel: bool,
    time_limit: Option<Duration>,
    setups: Memo<Setup, AtSetup<'p>>,
}

/// The part in one set-up: its analysis (with the mesh) and what was
/// computed on it.
pub struct AtSetup<'p> {
    pub analysis: PartAnalysis<'p>,
    /// Seconds the analysis took to build.
    pub built_seconds: f64,
    outcomes: Memo<Request, Outcome>,
    plans: Memo<(Request, RuleSet), Plan>,
}

impl<'p> Study<'p> {
    /// A study of `loaded` that uses worker threads inside its runs.
    pub fn new(loaded: &'p LoadedPart) -> Self {
        Self {
            loaded,
            parallel: true,
            time_limit: None,
            setups: Memo::default(),
        }
    }

    /// Whether the analyses use worker threads (a host running its own
    /// threads turns them off); the results are the same either way.
    pub fn with_parallelism(mut self, parallel: bool) -> Self {
        self.parallel = parallel;
        self
    }

    /// Let each use case on this study take at most `limit` (none by
    /// default); past it the use case fails with `budget_exceeded`.
    pub fn with_time_limit(mut self, limit: Option<Duration>) -> Self {
        self.time_limit = limit;
        self
    }

    pub fn loaded(&self) -> &'p LoadedPart {
        self.loaded
    }

    /// The name results give the part.
    pub fn name(&self) -> &'p str {
        &self.loaded.name
    }

    pub fn parallel(&self) -> bool {
        self.parallel
    }

    /// The part in `setup`, its analysis built the first time; the work
    /// starting now on it has the study's time limit.
    pub fn at(&self, setup: &Setup) -> Result<Arc<AtSetup<'p>>, StudyError> {
        setup.validate()?;
        let loaded = self.loaded;
        let at = self.setups.get_or_try(setup, || {
            let t0 = Instant::now();
            let analysis = PartAnalysis::with_graph(&loaded.part, &loaded.graph, setup.clone())
                .with_parallelism(self.parallel);
            Ok::<_, StudyError>(AtSetup {
                analysis,
                built_seconds: t0.elapsed().as_secs_f64(),
                outcomes: Memo::default(),
                plans: Memo::default(),
            })
        })?;
        at.analysis.budget().start(self.time_limit);
        Ok(at)
    }
}

impl AtSetup<'_> {
    /// The recognition outcome of `req` (whose set-up is this one).
    /// The study's parallelism decides (serial when it is serial, whatever
    /// `req.parallel` says; the results are the same).
    pub fn outcome(&self, req: &Request) -> Result<Arc<Outcome>, PipelineError> {
        let req = &self.as_run(req);
        self.outcomes
            .get_or_try(req, || thinwall_pipeline::run_on(&self.analysis, req))
    }

    /// `req` as this set-up runs it: serial when the study is.
    fn as_run(&self, req: &Request) -> Request {
        Request {
            parallel: self.analysis.is_parallel(),
            ..req.clone()
        }
    }

    /// The plan of the recognition of `req` with `rules`; `name` names the
    /// part in it.
    pub fn plan(
        &self,
        name: &str,
        req: &Request,
        rules: &RuleSet,
    ) -> Result<Arc<Plan>, StudyError> {
        let key = (self.as_run(req), rules.clone());
        self.plans.get_or_try(&key, || {
            let outcome = self
                .outcome(req)
                .map_err(|source| StudyError::Recognition {
                    file: name.to_string(),
                    source,
                })?;
            Ok(thinwall_plan::plan(name, &self.analysis, &outcome, rules)?)
        })
    }
}
