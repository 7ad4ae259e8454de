//! What a machining-feature run is asked: the set-up's tool axis to judge
//! features in, and the stock the part is cut from.

use thinwall_brep::Part;
use thinwall_geom::Vector3;
use thiserror::Error;

/// The stock the part is cut from.
#[derive(Clone, Copy, Debug, Default)]
pub enum StockSpec<'s> {
    /// The part's own oriented block (`Stock`): faces on it are stock.
    #[default]
    Block,
    /// The block grown by a uniform allowance on every side, mm: the
    /// part's faces on the block are faced (`MachiningKind::Face`).
    Offset(f64),
    /// A given solid (a blank, a casting envelope): the part's faces on
    /// its surface are stock; faces on the part's block off it are faced.
    Solid(&'s Part),
}

/// Options of a run.
#[derive(Clone, Copy, Debug, Default)]
pub struct Options<'s> {
    /// The set-up's tool axis (up, unit). When given, the block has it as
    /// an axis, features are entered from it where they can be, and each
    /// reports whether the tool reaches it (`reachable`); when not, every
    /// block direction is a candidate.
    pub up: Option<Vector3>,
    /// The largest tilt of the tool axis from up (5-axis), degrees; 0 for
    /// 3-axis.
    pub tilt_limit_deg: f64,
    pub stock: StockSpec<'s>,
}

/// Why machining features could not be found with these options.
#[derive(Debug, Error, PartialEq)]
pub enum MachiningError {
    #[error("stock offset must be a finite length of 0 mm or more, got {0}")]
    BadOffset(f64),
    #[error("the stock does not contain the part: the part reaches {by:.3} mm outside it")]
    StockTooSmall { by: f64 },
    #[error("the stock solid has no faces")]
    EmptyStock,
}

impl MachiningError {
    /// A stable machine-readable code for the error kind.
    pub fn code(&self) -> &'static str {
        match self {
            MachiningError::BadOffset(_) => "bad_offset",
            MachiningError::StockTooSmall { .. } => "stock_too_small",
            MachiningError::EmptyStock => "empty_stock",
        }
    }
}
