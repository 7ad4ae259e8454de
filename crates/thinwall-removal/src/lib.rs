//! The material to remove, exactly: stock minus part, cut into vertical
//! blocks over the cells of the arrangement of the part's projections on
//! the set-up plane (a vertical decomposition).
//!
//! Every face that is not vertical is a graph `z = h(x, y)` over its
//! projection ([`pieces`]); over one cell of the arrangement ([`cells`]) a
//! vertical line meets the same pieces in the same order, so the material
//! over a cell is a list of intervals between pieces, and the removal is
//! the stock's intervals minus those. A block's volume is the difference
//! of two fluxes `∫∫ h dA` over its cell ([`flux`]), exact for planes and
//! closed-form for cylinders and cones: the blocks add up to
//! volume(stock) − volume(part) to rounding, with no overlap and no gap by
//! construction. Projections of curved edges are sampled so that areas are
//! kept ([`sample`]).
//!
//! A block is reachable from up when nothing of the part lies above it.

pub mod cells;
pub mod clip;
pub mod facets;
pub mod flux;
mod fold;
mod halving;
mod inside;
pub mod locate;
pub mod moments;
pub mod outline;
pub mod pieces;
pub mod sample;
pub mod slab;

use cells::{arrange, arrange_on, Cover};
use geo::{Coord, MultiPolygon, Rect};
use pieces::{Facing, Piece};
use thinwall_analysis::parallel::Work;
use thinwall_analysis::PartAnalysis;
use thinwall_brep::Part;
use thinwall_geom::{Frame, Vector3};
use thiserror::Error;

/// Why the removal cannot be decomposed.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum RemovalError {
    #[error("face #{step_id} is {reason}")]
    UnsupportedFace { step_id: u64, reason: String },
    #[error("the stock does not contain the part over {area_mm2:.3} mm² of its footprint")]
    StockTooSmall { area_mm2: f64 },
    /// The blocks do not add up to stock − part (pieces whose projections
    /// overlap where they should meet): refused rather than a wrong volume.
    #[error("the removal does not add up: {volume_mm3:.3} mm³ off stock − part, worst over faces {}", faces.iter().map(|f| format!("#{f}")).collect::<Vec<_>>().join(", "))]
    Inconsistent { volume_mm3: f64, faces: Vec<u64> },
}

impl RemovalError {
    pub fn code(&self) -> &'static str {
        match self {
            RemovalError::UnsupportedFace { .. } => "unsupported_face",
            RemovalError::StockTooSmall { .. } => "stock_too_small",
            RemovalError::Inconsistent { .. } => "inconsistent",
        }
    }
}

/// The stock to remove from.
pub enum StockShape<'a> {
    /// A block in the removal frame: `lo`, `hi` corners.
    Block { lo: [f64; 3], hi: [f64; 3] },
    /// A given solid (a blank, a casting envelope).
    Solid(&'a Part),
}

impl<'a> StockShape<'a> {
    /// The stock a spec describes in a removal frame where the part's
    /// block is `lo`..`hi`, and its name for reports (`block`, `block + 2
    /// mm`, `solid`).
    pub fn of(
        spec: thinwall_machining::StockSpec<'a>,
        mut lo: [f64; 3],
        mut hi: [f64; 3],
    ) -> (Self, String) {
        use thinwall_machining::StockSpec;
        match spec {
            StockSpec::Solid(s) => (StockShape::Solid(s), "solid".to_string()),
            StockSpec::Offset(mm) if mm > 0.0 => {
                for k in 0..3 {
                    lo[k] -= mm;
                    hi[k] += mm;
                }
                (StockShape::Block { lo, hi }, format!("block + {mm} mm"))
            }
            StockSpec::Offset(_) | StockSpec::Block => {
                (StockShape::Block { lo, hi }, "block".to_string())
            }
        }
    }
}

/// A block's lower or upper end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// A horizontal plane of the block stock, mm.
    Flat(f64),
    /// A piece of the part.
    Part(usize),
    /// A piece of the stock solid.
    Stock(usize),
}

/// Material to remove over one cell, between two bounds.
#[derive(Clone, Debug)]
pub struct Block {
    pub cell: usize,
    pub lower: Bound,
    pub upper: Bound,
    /// Nothing of the part lies above it.
    pub reachable: bool,
    /// Nothing of the part lies below it: a set-up from the opposite side
    /// reaches it.
    pub open_below: bool,
    /// Taken already by a set-up from the opposite side, done before this
    /// one ([`Removal::after_opposite`]).
    pub cleared: bool,
    pub volume: f64,
}

/// The decomposition.
pub struct Removal {
    /// z = the set-up's up.
    pub frame: Frame,
    pub part_pieces: Vec<Piece>,
    pub stock_pieces: Vec<Piece>,
    pub cells: Vec<cells::Cell>,
    /// Per cell, the indices into the band list it lies in.
    pub cell_bands: Vec<Vec<usize>>,
    pub blocks: Vec<Block>,
    pub stock_volume: f64,
    pub part_volume: f64,
    /// The part's vertical faces, for which faces a block touches.
    pub vertical: Vec<pieces::Vertical>,
    /// Vertical faces by grid square, to find those near a point.
    vertical_grid: Grid,
    /// The block stock's corners `lo`, `hi` (none for a given solid), mm.
    block: Option<([f64; 3], [f64; 3])>,
    /// Removal over cells narrower than [`SLIVER_WIDTH`] (noise of the
    /// booleans where edges coincide up to rounding) and over cells between
    /// a vertical face's edges that the file puts apart (narrower than
    /// twice [`Removal::edge_gap`], where the part's crossings do not
    /// alternate), left out, mm³.
    pub sliver_volume: f64,
    /// The part's size (its bounding diagonal), mm: tolerances scale with it.
    pub size: f64,
    /// The faces taken as triangles (not graphs of a kind the removal
    /// takes exactly), and the volume bound that implies.
    pub meshed: pieces::Meshed,
    /// Why the blocks do not add up to stock − part, if they do not (see
    /// [`Removal::checked`]).
    pub inconsistency: Option<RemovalError>,
}

pub use thinwall_geom::tolerance::SLIVER_WIDTH;

/// The widest lens two outlines of one curve can leave between them, each
/// within the outline deviation of the curve, mm (`sample.rs`): a cell no
/// wider whose column crosses the part's faces out of turn is such a lens.
const OUTLINE_LENS_MM: f64 = 2.0 * sample::OUTLINE_DEVIATION_MM;

/// Corners of a cell toward which another point to read its column is
/// tried, at most (twice: half-way and nine tenths of the way).
const COLUMN_POINT_TRIES: usize = 16;

fn mean_width(p: &geo::Polygon<f64>) -> f64 {
    use geo::{Euclidean, Length};
    let perimeter: f64 = std::iter::once(p.exterior())
        .chain(p.interiors())
        .map(|r| Euclidean.length(r))
        .sum();
    if perimeter > 0.0 {
        2.0 * flux::area(p) / perimeter
    } else {
        0.0
    }
}

/// The removal frame of a set-up: z is up, x and y the stock's other two
/// axes (the longer first), right-handed.
pub fn frame_of(a: &PartAnalysis, up: Vector3) -> (Frame, [f64; 3], [f64; 3]) {
    let stock = thinwall_machining::stock::Stock::of(a, Some(up));
    let k_up = (0..3)
        .max_by(|&i, &j| {
            stock.axes[i]
                .dot(&up)
                .abs()
                .total_cmp(&stock.axes[j].dot(&up).abs())
        })
        .unwrap_or(2);
    let range = |k: usize| (-stock.plane_offset(2 * k), stock.plane_offset(2 * k + 1));
    let others: Vec<usize> = (0..3).filter(|&k| k != k_up).collect();
    let ext = |k: usize| range(k).1 - range(k).0;
    let (mut i, mut j) = (others[0], others[1]);
    if ext(j) > ext(i) + 1e-9 * ext(i).max(1.0) {
        std::mem::swap(&mut i, &mut j);
    }
    let x = stock.axes[i];
    let mut y = stock.axes[j];
    let mut flip_y = false;
    if x.cross(&y).dot(&up) < 0.0 {
        y = -y;
        flip_y = true;
    }
    let frame = Frame {
        origin: thinwall_geom::Point3::origin(),
        x,
        y,
        z: up,
    };
    let (xlo, xhi) = range(i);
    let (mut ylo, mut yhi) = range(j);
    if flip_y {
        (ylo, yhi) = (-yhi, -ylo);
    }
    let (mut zlo, mut zhi) = range(k_up);
    if stock.axes[k_up].dot(&up) < 0.0 {
        (zlo, zhi) = (-zhi, -zlo);
    }
    (frame, [xlo, ylo, zlo], [xhi, yhi, zhi])
}

/// The rectangle the arrangement starts from: the block stock's
/// footprint, or the pieces' box padded by 1e-3 of the part's size.
fn footprint<'a>(
    stock: &StockShape,
    pieces: impl Iterator<Item = &'a Piece>,
    size: f64,
) -> Rect<f64> {
    if let StockShape::Block { lo, hi } = stock {
        return Rect::new(Coord { x: lo[0], y: lo[1] }, Coord { x: hi[0], y: hi[1] });
    }
    let mut r = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for p in pieces {
        r = [
            r[0].min(p.bbox.min().x),
            r[1].min(p.bbox.min().y),
            r[2].max(p.bbox.max().x),
            r[3].max(p.bbox.max().y),
        ];
    }
    let pad = 1e-3 * size;
    Rect::new(
        Coord {
            x: r[0] - pad,
            y: r[1] - pad,
        },
        Coord {
            x: r[2] + pad,
            y: r[3] + pad,
        },
    )
}

/// The regions the arrangement cuts along: the pieces' projections (part
/// first, then stock), then the bands.
fn covers<'a>(
    pieces: impl Iterator<Item = &'a Piece>,
    bands: &'a [MultiPolygon<f64>],
) -> Vec<Cover<'a>> {
    let pieces: Vec<&Piece> = pieces.collect();
    // With a meshed face among them, every cut goes through i_overlay 9:
    // cells cut by a many-cornered region make geo's i_overlay 4.5 panic
    // (the ledger); a removal of exact faces keeps geo's booleans.
    let robust = pieces
        .iter()
        .any(|p| matches!(p.height, pieces::Height::Facets { .. }));
    let mut covers: Vec<Cover> = pieces
        .iter()
        .map(|p| Cover {
            region: &p.region,
            bbox: p.bbox,
            robust,
        })
        .collect();
    for b in bands {
        let bbox = geo::BoundingRect::bounding_rect(b).unwrap_or(Rect::new(
            Coord { x: 0.0, y: 0.0 },
            Coord { x: 0.0, y: 0.0 },
        ));
        covers.push(Cover {
            region: b,
            bbox,
            robust,
        });
    }
    covers
}

/// The vertical columns over the cells: the pieces a cell's covers index
/// (part, then stock solid, then bands).
struct Columns<'a> {
    part: &'a [Piece],
    stock_pieces: &'a [Piece],
    stock: &'a StockShape<'a>,
    size: f64,
    /// The vertical faces whose edges lie off their surfaces by more than a
    /// sliver's width.
    gapped: Vec<&'a pieces::Vertical>,
}

/// What the columns hold, added up column by column.
struct Column {
    blocks: Vec<Block>,
    /// The cells' area where part material lies outside the stock, mm².
    missing: f64,
    /// Removal left out because its cell is a sliver, mm³.
    sliver_volume: f64,
}

impl Columns<'_> {
    /// The bands a cell lies in.
    fn bands_of(&self, c: &cells::Cell) -> Vec<usize> {
        let first_band = self.part.len() + self.stock_pieces.len();
        c.covers
            .iter()
            .filter(|&&k| k >= first_band)
            .map(|&k| k - first_band)
            .collect()
    }

    /// Whether cell `c`, `width` wide on average, lies between the two
    /// outlines of a vertical face whose edges the file puts off its
    /// surface: no wider than twice the face's gap, and that near its edges.
    fn between_edges(&self, c: &cells::Cell, width: f64) -> bool {
        use geo::{Distance, Euclidean, Line};
        let Some(pt) = geo::InteriorPoint::interior_point(&c.poly) else {
            return false;
        };
        self.gapped.iter().any(|v| {
            let reach = 2.0 * v.gap + SLIVER_WIDTH * self.size;
            width <= reach
                && pt.x() >= v.bbox.min().x - reach
                && pt.x() <= v.bbox.max().x + reach
                && pt.y() >= v.bbox.min().y - reach
                && pt.y() <= v.bbox.max().y + reach
                && v.segments
                    .iter()
                    .any(|&[a, b]| Euclidean.distance(&Line::new(a, b), &pt) <= reach)
        })
    }

    /// The column's volume of stock − part by its faces' fluxes (up-facing
    /// faces add, down-facing ones take away), mm³.
    fn flux_volume(&self, c: &cells::Cell) -> f64 {
        let np = self.part.len();
        let signed = |b: Bound, facing: Facing| {
            let f = flux::flux(&b.height(self.part, self.stock_pieces), &c.poly);
            if facing == Facing::Up {
                f
            } else {
                -f
            }
        };
        let stock: f64 = match self.stock {
            StockShape::Block { lo, hi } => {
                signed(Bound::Flat(hi[2]), Facing::Up) + signed(Bound::Flat(lo[2]), Facing::Down)
            }
            StockShape::Solid(_) => c
                .covers
                .iter()
                .filter(|&&k| k >= np && k < np + self.stock_pieces.len())
                .map(|&k| signed(Bound::Stock(k - np), self.stock_pieces[k - np].facing))
                .sum(),
        };
        let part: f64 = c
            .covers
            .iter()
            .filter(|&&k| k < np)
            .map(|&k| signed(Bound::Part(k), self.part[k].facing))
            .sum();
        stock - part
    }

    /// Where cell `c`'s column is read: its interior point, unless two of
    /// its bounds meet there (a dome's pole on the stock's top, a tube's
    /// crest), where the block between them would read as empty; then the
    /// point, among some between it and the cell's corners, where the
    /// bounds stand furthest apart.
    fn column_point(&self, c: &cells::Cell) -> geo::Point<f64> {
        use geo::Contains;
        let first = geo::InteriorPoint::interior_point(&c.poly).expect("a cell has an inside");
        let tol = 1e-6 * self.size;
        let spread0 = self.spread(c, &first);
        if spread0 > tol {
            return first;
        }
        let corners = &c.poly.exterior().0;
        let every = (corners.len() / COLUMN_POINT_TRIES).max(1);
        let mut best = (spread0, first);
        for v in corners.iter().step_by(every) {
            for share in [0.5, 0.9] {
                let p = geo::Point::new(
                    first.x() + (v.x - first.x()) * share,
                    first.y() + (v.y - first.y()) * share,
                );
                if !c.poly.contains(&p) {
                    continue;
                }
                let spread = self.spread(c, &p);
                if spread > best.0 + tol {
                    best = (spread, p);
                }
            }
        }
        best.1
    }

    /// The least height between two of cell `c`'s bounds at `p`, mm.
    fn spread(&self, c: &cells::Cell, p: &geo::Point<f64>) -> f64 {
        let np = self.part.len();
        let mut h: Vec<f64> = c
            .covers
            .iter()
            .filter_map(|&k| match k {
                k if k < np => Some(self.part[k].height.at(p.x(), p.y())),
                k if k < np + self.stock_pieces.len() => {
                    Some(self.stock_pieces[k - np].height.at(p.x(), p.y()))
                }
                _ => None,
            })
            .collect();
        if let StockShape::Block { lo, hi } = self.stock {
            h.extend([lo[2], hi[2]]);
        }
        h.sort_by(f64::total_cmp);
        h.windows(2)
            .map(|w| w[1] - w[0])
            .fold(f64::INFINITY, f64::min)
    }

    /// The intervals of part material and of stock along the column, and
    /// whether the part's crossings alternate (down, up, down, …).
    fn intervals(&self, c: &cells::Cell) -> (Vec<Interval>, Vec<Interval>, bool) {
        let (np, ns) = (self.part.len(), self.stock_pieces.len());
        let pt = self.column_point(c);
        let at = |pc: &Piece| pc.height.at(pt.x(), pt.y());
        let part_cross: Vec<(f64, Facing, Bound)> = c
            .covers
            .iter()
            .filter(|&&k| k < np)
            .map(|&k| (at(&self.part[k]), self.part[k].facing, Bound::Part(k)))
            .collect();
        let stock_cross: Vec<(f64, Facing, Bound)> = match self.stock {
            StockShape::Block { lo, hi } => vec![
                (lo[2], Facing::Down, Bound::Flat(lo[2])),
                (hi[2], Facing::Up, Bound::Flat(hi[2])),
            ],
            StockShape::Solid(_) => c
                .covers
                .iter()
                .filter(|&&k| k >= np && k < np + ns)
                .map(|&k| {
                    let piece = &self.stock_pieces[k - np];
                    (at(piece), piece.facing, Bound::Stock(k - np))
                })
                .collect(),
        };
        let alternate = alternates(&part_cross);
        (intervals(part_cross), intervals(stock_cross), alternate)
    }

    /// The blocks over cell `ci` (stock intervals minus part intervals),
    /// and what else its column holds.
    fn blocks_over(&self, ci: usize, c: &cells::Cell) -> CellColumn {
        let mut column = CellColumn::default();
        let (solid, stock_iv, alternate) = self.intervals(c);
        let width = mean_width(&c.poly);
        if !alternate && (width <= OUTLINE_LENS_MM || self.between_edges(c, width)) {
            // Between a vertical face's edges that the file puts apart, or
            // between two outlines of one curve cut differently (a lens no
            // wider than two outline deviations): the column's volume by
            // its faces' fluxes, in no block.
            column.slivers.push(self.flux_volume(c));
            return column;
        }
        // Part material outside the stock: the stock is too small.
        for (lo, hi) in &solid {
            let inside: f64 = stock_iv
                .iter()
                .map(|(a, b)| (hi.0.min(b.0) - lo.0.max(a.0)).max(0.0))
                .sum();
            if hi.0 - lo.0 - inside > 1e-6 * self.size {
                column.missing.push(c.area);
            }
        }
        let top = stock_iv.last().map(|iv| iv.1 .0);
        let bottom = stock_iv.first().map(|iv| iv.0 .0);
        let sliver = width < SLIVER_WIDTH * self.size;
        for (lo, hi) in subtract(&stock_iv, &solid) {
            let vol = |b: &Bound| flux::flux(&b.height(self.part, self.stock_pieces), &c.poly);
            let volume = vol(&hi.1) - vol(&lo.1);
            if sliver {
                column.slivers.push(volume);
                continue;
            }
            column.blocks.push(Block {
                cell: ci,
                lower: lo.1,
                upper: hi.1,
                reachable: Some(hi.0) == top,
                open_below: Some(lo.0) == bottom,
                cleared: false,
                volume,
            });
        }
        column
    }
}

/// What one cell's column holds, in the order [`Column`] adds it up.
#[derive(Default)]
struct CellColumn {
    blocks: Vec<Block>,
    /// Areas where part material lies outside the stock, mm².
    missing: Vec<f64>,
    /// Volumes left out as slivers, mm³.
    slivers: Vec<f64>,
}

/// A bound as an exact key (within one column, where a cut height is the
/// same number on both sides of it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BoundId {
    Flat(u64),
    Part(usize),
    Stock(usize),
}

impl Bound {
    pub fn id(&self) -> BoundId {
        match *self {
            Bound::Flat(z) => BoundId::Flat(z.to_bits()),
            Bound::Part(i) => BoundId::Part(i),
            Bound::Stock(i) => BoundId::Stock(i),
        }
    }

    /// Its height function (a flat bound is a horizontal plane), given the
    /// part's and the stock's pieces.
    fn height(&self, part: &[Piece], stock: &[Piece]) -> pieces::Height {
        match *self {
            Bound::Flat(z) => pieces::Height::plane(z, 0.0, 0.0),
            Bound::Part(i) => part[i].height.clone(),
            Bound::Stock(i) => stock[i].height.clone(),
        }
    }
}

/// A removal's faces seen from up and its cells, before the columns over
/// them: what [`Removal::new`] and [`Removal::with_bands`] share.
struct Arranged<'s, 'p> {
    frame: Frame,
    stock: &'s StockShape<'p>,
    size: f64,
    meshed: pieces::Meshed,
    part_pieces: Vec<Piece>,
    stock_pieces: Vec<Piece>,
    start: Rect<f64>,
    cells: Vec<cells::Cell>,
}

/// Cells below this area (noise of the booleans) are dropped, mm².
fn min_cell_area(size: f64) -> f64 {
    (1e-7 * size).powi(2)
}

impl Removal {
    /// Decompose `stock − part` in `frame`, cutting cells also along every
    /// band (regions the planner wants features to follow).
    /// The faces' pieces and the cells are made on `work`'s threads (the
    /// same result either way).
    pub fn new(
        part: &Part,
        frame: Frame,
        stock: &StockShape,
        bands: &[MultiPolygon<f64>],
        size: f64,
        work: Work,
    ) -> Result<Self, RemovalError> {
        let deviation = thinwall_geom::tolerance::machining_deviation(size);
        let mut meshed = pieces::Meshed::default();
        let part_pieces = pieces::pieces(part, &frame, (deviation, work), &mut meshed)?;
        let stock_pieces = match stock {
            StockShape::Solid(s) => pieces::pieces(s, &frame, (deviation, work), &mut meshed)?,
            StockShape::Block { .. } => vec![],
        };
        let start = footprint(stock, part_pieces.iter().chain(&stock_pieces), size);
        let covers = covers(part_pieces.iter().chain(&stock_pieces), bands);
        let cells = arrange(start.to_polygon(), &covers, min_cell_area(size), work);
        Self::columns(
            part,
            Arranged {
                frame,
                stock,
                size,
                meshed,
                part_pieces,
                stock_pieces,
                start,
                cells,
            },
            work,
        )
    }

    /// What [`Removal::new`] gives with `bands` in the same frame and of
    /// the same block `stock` as this removal, made without bands: the
    /// bands are the arrangement's last covers, so this removal's pieces
    /// and cells are where it would stand before them, and only the bands
    /// are cut (the plan's removal after the proposal's, whose pieces and
    /// cells are most of its cost). `None` when this removal has bands or
    /// another stock.
    pub fn with_bands(
        &self,
        part: &Part,
        stock: &StockShape,
        bands: &[MultiPolygon<f64>],
        work: Work,
    ) -> Option<Result<Self, RemovalError>> {
        // The same corners bit for bit (a zero's sign too, which would
        // show in the cells' coordinates).
        let bits = |c: &[f64; 3]| c.map(f64::to_bits);
        let same_block = matches!((stock, self.block), (StockShape::Block { lo, hi }, Some((l, h)))
            if bits(lo) == bits(&l) && bits(hi) == bits(&h));
        // Covers past the pieces' are bands this removal was cut by.
        let first = self.part_pieces.len() + self.stock_pieces.len();
        let banded = self
            .cells
            .iter()
            .any(|c| c.covers.iter().any(|&i| i >= first));
        if banded || !same_block {
            return None;
        }
        let covers = covers(self.part_pieces.iter().chain(&self.stock_pieces), bands);
        let cut = (first, min_cell_area(self.size));
        let cells = arrange_on(self.cells.clone(), &covers, cut, work);
        Some(Self::columns(
            part,
            Arranged {
                frame: self.frame,
                stock,
                size: self.size,
                meshed: self.meshed.clone(),
                part_pieces: self.part_pieces.clone(),
                stock_pieces: self.stock_pieces.clone(),
                start: footprint(stock, std::iter::empty(), self.size),
                cells,
            },
            work,
        ))
    }

    /// The removal over arranged cells: each cell's bands, its columns'
    /// blocks, and the check that they add up.
    fn columns(part: &Part, x: Arranged, work: Work) -> Result<Self, RemovalError> {
        let Arranged {
            frame,
            stock,
            size,
            meshed,
            part_pieces,
            stock_pieces,
            start,
            cells,
        } = x;
        let min_area = min_cell_area(size);
        let vertical = pieces::vertical_faces(part, &frame);
        let columns = Columns {
            part: &part_pieces,
            stock_pieces: &stock_pieces,
            stock,
            size,
            gapped: vertical
                .iter()
                .filter(|v| v.gap > SLIVER_WIDTH * size)
                .collect(),
        };
        let cell_bands = cells.iter().map(|c| columns.bands_of(c)).collect();
        let mut column = Column {
            blocks: Vec::new(),
            missing: 0.0,
            sliver_volume: 0.0,
        };
        // Each cell's column alone, on `work`'s threads; added up in the
        // cells' order (the same sums, bit for bit).
        let order: Vec<usize> = (0..cells.len()).collect();
        for one in work.map(&order, |&ci| columns.blocks_over(ci, &cells[ci])) {
            column.blocks.extend(one.blocks);
            for m in one.missing {
                column.missing += m;
            }
            for v in one.slivers {
                column.sliver_volume += v;
            }
        }
        let Column {
            blocks,
            missing,
            sliver_volume,
        } = column;
        if missing > min_area.max(1e-6 * size * size) {
            return Err(RemovalError::StockTooSmall { area_mm2: missing });
        }
        let part_volume = signed_volume(&part_pieces);
        let stock_volume = match stock {
            StockShape::Block { lo, hi } => (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]),
            StockShape::Solid(_) => signed_volume(&stock_pieces),
        };
        let removed = blocks.iter().map(|b| b.volume).sum::<f64>() + sliver_volume;
        let off = (removed - (stock_volume - part_volume)).abs() > 1e-6 * stock_volume.abs();
        let inconsistency = off.then(|| {
            inconsistent(
                removed - (stock_volume - part_volume),
                &cells,
                &blocks,
                &part_pieces,
                &stock_pieces,
                stock,
            )
        });
        let vertical_grid = Grid::new(start, vertical.iter().map(|v| v.bbox), 1e-6 * size);
        let block = match stock {
            StockShape::Block { lo, hi } => Some((*lo, *hi)),
            StockShape::Solid(_) => None,
        };
        Ok(Self {
            block,
            size,
            meshed,
            vertical_grid,
            sliver_volume,
            vertical,
            frame,
            part_pieces,
            stock_pieces,
            cells,
            cell_bands,
            blocks,
            stock_volume,
            part_volume,
            inconsistency,
        })
    }

    /// The decomposition, if its blocks add up to stock − part (to 1e-6
    /// of the stock); else [`RemovalError::Inconsistent`], naming faces. A
    /// plan or operations use only a checked removal: never a wrong volume.
    pub fn checked(self) -> Result<Self, RemovalError> {
        match self.inconsistency {
            Some(e) => Err(e),
            None => Ok(self),
        }
    }

    /// The lowest and highest height of a bound over a region, mm.
    pub fn height_range(&self, b: &Bound, region: &MultiPolygon<f64>) -> [f64; 2] {
        self.height_of(b).range_over(region)
    }

    /// A bound's height function (a flat bound is a horizontal plane).
    pub fn height_of(&self, b: &Bound) -> pieces::Height {
        b.height(&self.part_pieces, &self.stock_pieces)
    }

    /// Indices of the vertical faces whose box (grown by the grid's
    /// tolerance) may hold `(x, y)`.
    pub fn vertical_near(&self, x: f64, y: f64) -> &[usize] {
        self.vertical_grid.at(x, y)
    }

    /// The `step_id` of part piece `i`'s face.
    pub fn part_step_id(&self, i: usize) -> u64 {
        self.part_pieces[i].step_id
    }

    /// The block stock's bottom height, mm (NaN for a given solid).
    pub fn stock_bottom(&self) -> f64 {
        self.block.map_or(f64::NAN, |(lo, _)| lo[2])
    }

    /// The axis (world, unit) of a bound that is a half cylinder.
    pub fn cylinder_axis(&self, b: &Bound) -> Option<Vector3> {
        let Bound::Part(i) = *b else { return None };
        match self.part_pieces[i].height {
            pieces::Height::Cylinder { a, .. } => {
                Some(self.frame.vector_to_world(&Vector3::new(a[0], a[1], 0.0)))
            }
            _ => None,
        }
    }

    /// Sum of the blocks' volumes, mm³.
    /// This removal after a set-up from the opposite side: that set-up
    /// took every block it reached, those with nothing of the part below
    /// them here (the pockets on its side, the through holes, the stock
    /// round the part), so they are `cleared`; what this side reaches
    /// besides is what that set-up could not (the far side of a web
    /// pocketed from both sides).
    pub fn after_opposite(mut self) -> Self {
        for b in &mut self.blocks {
            b.cleared = b.open_below;
        }
        self
    }

    /// The volume of the blocks an earlier set-up took, mm³.
    pub fn cleared_volume(&self) -> f64 {
        self.blocks
            .iter()
            .filter(|b| b.cleared)
            .map(|b| b.volume)
            .sum()
    }

    /// How far the edges of the part's vertical faces lie off their
    /// surfaces, at most (the file's gaps), mm.
    pub fn edge_gap(&self) -> f64 {
        self.vertical.iter().map(|v| v.gap).fold(0.0, f64::max)
    }

    pub fn removed_volume(&self) -> f64 {
        self.blocks.iter().map(|b| b.volume).sum()
    }

    /// The lowest and highest height of a bound over a cell, mm.
    pub fn bound_range(&self, b: &Bound) -> [f64; 2] {
        match *b {
            Bound::Flat(z) => [z, z],
            Bound::Part(i) => self.part_pieces[i].z_range,
            Bound::Stock(i) => self.stock_pieces[i].z_range,
        }
    }
}

/// A solid's volume from its pieces: Σ ±∫∫ h (divergence theorem with
/// the field (0, 0, z)).
/// The error of a removal whose blocks do not add up, naming the part's
/// faces over the cell that is most off.
fn inconsistent(
    off: f64,
    cells: &[cells::Cell],
    blocks: &[Block],
    part_pieces: &[Piece],
    stock_pieces: &[Piece],
    stock: &StockShape,
) -> RemovalError {
    let np = part_pieces.len();
    let signed = |p: &Piece, c: &cells::Cell| {
        let f = flux::flux(&p.height, &c.poly);
        if p.facing == Facing::Up {
            f
        } else {
            -f
        }
    };
    let mut by_cell = vec![0.0; cells.len()];
    for b in blocks {
        by_cell[b.cell] += b.volume;
    }
    let worst = cells
        .iter()
        .enumerate()
        .map(|(ci, c)| {
            let stock_col = match stock {
                StockShape::Block { lo, hi } => (hi[2] - lo[2]) * c.area,
                StockShape::Solid(_) => c
                    .covers
                    .iter()
                    .filter(|&&k| k >= np && k < np + stock_pieces.len())
                    .map(|&k| signed(&stock_pieces[k - np], c))
                    .sum(),
            };
            let part_col: f64 = c
                .covers
                .iter()
                .filter(|&&k| k < np)
                .map(|&k| signed(&part_pieces[k], c))
                .sum();
            (ci, (stock_col - part_col - by_cell[ci]).abs())
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map(|(ci, _)| ci);
    let mut faces: Vec<u64> = worst
        .map(|ci| {
            cells[ci]
                .covers
                .iter()
                .filter(|&&k| k < np)
                .map(|&k| part_pieces[k].step_id)
                .collect()
        })
        .unwrap_or_default();
    faces.sort_unstable();
    faces.dedup();
    RemovalError::Inconsistent {
        volume_mm3: off,
        faces,
    }
}

pub fn signed_volume(pieces: &[Piece]) -> f64 {
    pieces
        .iter()
        .map(|p| {
            let f: f64 = p
                .region
                .0
                .iter()
                .map(|poly| flux::flux(&p.height, poly))
                .sum();
            match p.facing {
                Facing::Up => f,
                Facing::Down => -f,
            }
        })
        .sum()
}

type End = (f64, Bound);

/// Material between two ends along a vertical line.
type Interval = (End, End);

/// Material intervals along a vertical line from the faces it crosses:
/// entering through a face facing down, leaving through one facing up.
fn intervals(mut cross: Vec<(f64, Facing, Bound)>) -> Vec<(End, End)> {
    cross.sort_by(|a, b| {
        a.0.total_cmp(&b.0)
            .then_with(|| (a.1 == Facing::Down).cmp(&(b.1 == Facing::Down)))
    });
    let mut out = Vec::new();
    let mut depth = 0i32;
    let mut start: Option<End> = None;
    for (z, facing, b) in cross {
        match facing {
            Facing::Down => {
                if depth == 0 {
                    start = Some((z, b));
                }
                depth += 1;
            }
            Facing::Up => {
                if depth == 1 {
                    if let Some(s) = start.take() {
                        out.push((s, (z, b)));
                    }
                }
                depth = (depth - 1).max(0);
            }
        }
    }
    out
}

/// Whether crossings sorted by height alternate down, up, down, … (a
/// column through an exact solid; a file's gaps can break it).
fn alternates(cross: &[(f64, Facing, Bound)]) -> bool {
    let mut sorted: Vec<(f64, Facing)> = cross.iter().map(|c| (c.0, c.1)).collect();
    sorted.sort_by(|a, b| {
        a.0.total_cmp(&b.0)
            .then_with(|| (a.1 == Facing::Down).cmp(&(b.1 == Facing::Down)))
    });
    sorted.len().is_multiple_of(2)
        && sorted
            .chunks(2)
            .all(|p| p[0].1 == Facing::Down && p[1].1 == Facing::Up)
}

/// `a − b` for sorted, disjoint interval lists.
fn subtract(a: &[(End, End)], b: &[(End, End)]) -> Vec<(End, End)> {
    let mut out = Vec::new();
    for &(lo, hi) in a {
        let mut cur = lo;
        for &(blo, bhi) in b {
            if bhi.0 <= cur.0 || blo.0 >= hi.0 {
                continue;
            }
            if blo.0 > cur.0 {
                out.push((cur, blo));
            }
            if bhi.0 > cur.0 {
                cur = bhi;
            }
        }
        if hi.0 > cur.0 {
            out.push((cur, hi));
        }
    }
    out
}

/// A uniform grid over a rectangle, each square listing the boxes that
/// overlap it.
struct Grid {
    origin: (f64, f64),
    step: (f64, f64),
    n: usize,
    squares: Vec<Vec<usize>>,
}

impl Grid {
    const SIDE: usize = 128;

    fn new(area: Rect<f64>, boxes: impl Iterator<Item = Rect<f64>>, grow: f64) -> Self {
        let n = Self::SIDE;
        let step = (
            (area.width() / n as f64).max(1e-12),
            (area.height() / n as f64).max(1e-12),
        );
        let origin = (area.min().x, area.min().y);
        let mut squares = vec![Vec::new(); n * n];
        let idx = |v: f64, o: f64, s: f64| (((v - o) / s).floor().max(0.0) as usize).min(n - 1);
        for (i, b) in boxes.enumerate() {
            let (x0, x1) = (
                idx(b.min().x - grow, origin.0, step.0),
                idx(b.max().x + grow, origin.0, step.0),
            );
            let (y0, y1) = (
                idx(b.min().y - grow, origin.1, step.1),
                idx(b.max().y + grow, origin.1, step.1),
            );
            for gx in x0..=x1 {
                for gy in y0..=y1 {
                    squares[gy * n + gx].push(i);
                }
            }
        }
        Self {
            origin,
            step,
            n,
            squares,
        }
    }

    fn at(&self, x: f64, y: f64) -> &[usize] {
        let idx =
            |v: f64, o: f64, s: f64| (((v - o) / s).floor().max(0.0) as usize).min(self.n - 1);
        &self.squares
            [idx(y, self.origin.1, self.step.1) * self.n + idx(x, self.origin.0, self.step.0)]
    }
}
