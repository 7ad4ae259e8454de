//! The command line: clap's view of every command and its flags, and the
//! one step from flags to a use case's request (reading the files a flag
//! names). Every rule about a value is the request's `check()`, not here.

use crate::failure::Failure;
use clap::builder::TypedValueParser;
use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use thinwall_study::Format;

/// A `--format` parser that takes the formats `names` (of `Format`).
fn formats(names: &'static [&'static str]) -> impl TypedValueParser<Value = Format> {
    clap::builder::PossibleValuesParser::new(names)
        .map(|s| s.parse::<Format>().expect("a listed format is a format"))
}

#[derive(Parser)]
#[command(
    name = "thinwall",
    version,
    about = "Stiffness features and machining features of thin-walled parts, from STEP"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
    /// Most seconds a command may work on one part (each part of a
    /// `batch`); past it the command stops with `budget_exceeded` (exit 1).
    /// 0 for no limit.
    #[arg(
        allow_negative_numbers = true,
        long,
        global = true,
        default_value_t = 600.0
    )]
    pub time_limit: f64,
}

impl Cli {
    /// The time limit, or a usage failure for a value that is not one.
    pub fn time_limit(&self) -> Result<Option<std::time::Duration>, Failure> {
        match self.time_limit {
            0.0 => Ok(None),
            t if t.is_finite() && t > 0.0 && t <= 1e7 => {
                Ok(Some(std::time::Duration::from_secs_f64(t)))
            }
            t => Err(Failure::Usage(format!(
                "--time-limit: must be a number of seconds from 0 (no limit) to 1e7, got {t}"
            ))),
        }
    }
}

#[derive(Subcommand)]
pub enum Command {
    /// Read a part and report its bodies, faces, edges and their convexity.
    Inspect {
        /// The STEP file (AP203, AP214 or AP242).
        part: PathBuf,
        /// Output format.
        #[arg(long, value_parser = formats(&["text", "json"]), default_value = "text")]
        format: Format,
    },
    /// Recognize stiffness features: walls (web, rib, flange), thinness,
    /// holes, cut-outs, notches, fillets, chamfers.
    Recognize(RecognizeArgs),
    /// Plan the machining order of the stiffness features: sequence
    /// constraints from rules (docs/PLANNING.md), each decision explained.
    Plan(PlanArgs),
    /// Recognize many parts in parallel: one report per part in OUT, a
    /// summary (summary.jsonl and a table), progress on stderr. A bad file
    /// is reported, not fatal; exit 1 when any part failed.
    Batch(BatchArgs),
    /// Compare a part's recognition with a stored one (a regression check
    /// of your own parts): features added, lost, changed kind or size,
    /// thinness, connections. Exit 1 on any difference.
    Check(CheckArgs),
    /// Accessibility of the part's faces: how much of each face and wall
    /// side a tool and its holder reach with material in the way, and
    /// whether each planar face can be flank milled (its G-zone, Harik &
    /// Ris; docs/ACCESS.md).
    Access(AccessArgs),
    /// Operations of a set-up: layers from the stock's top (and at every
    /// flat face), cutter fields, the largest tools that fit with their
    /// rest areas and regions (boundary, full cut, roughing), walls' and
    /// floors' finishing, pockets finished by their corner radius and floor
    /// fillet, holes spotted, drilled by subtype, countersunk and
    /// chamfered, in an order that cuts tool changes (docs/OPERATIONS.md).
    Operations(OperationsArgs),
    /// Size a thin wall's machining features (B_RF, h_RF, H_RF) with the
    /// step-approach bending model (docs/PLANNING.md).
    SizeWall(SizeWallArgs),
    /// Classify machining-feature volumes (pocket, slot, step, …) by shape
    /// and by which faces touch the part or volumes not removed before them.
    Classify(ClassifyArgs),
}

fn parse_before(s: &str) -> Result<(usize, usize), String> {
    let (a, b) = s
        .split_once(':')
        .ok_or_else(|| format!("expected A:B, got '{s}'"))?;
    let a = a
        .trim()
        .parse()
        .map_err(|_| format!("'{a}' is not a volume index"))?;
    let b = b
        .trim()
        .parse()
        .map_err(|_| format!("'{b}' is not a volume index"))?;
    Ok((a, b))
}

/// The flags of `recognize`.
#[derive(clap::Args)]
pub struct RecognizeArgs {
    /// The STEP file.
    pub part: PathBuf,
    #[command(flatten)]
    pub flags: RecognizeFlags,
    /// Print the time of every stage and every warning to stderr.
    #[arg(long)]
    pub verbose: bool,
    /// Output format.
    #[arg(long, value_parser = formats(&["text", "json", "svg", "html"]), default_value = "json")]
    pub format: Format,
    /// Write to this file instead of stdout.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

/// The flags of `plan`.
#[derive(clap::Args)]
pub struct PlanArgs {
    /// The STEP file.
    pub part: PathBuf,
    #[command(flatten)]
    pub flags: RecognizeFlags,
    /// A TOML file of sequence rules (default: the shipped five).
    #[arg(long)]
    pub rules: Option<PathBuf>,
    /// Write each machining feature as a STEP solid (`V1.step`, …) here;
    /// a later set-up's into `setup-2/`, ….
    #[arg(long)]
    pub volumes_dir: Option<PathBuf>,
    /// Output format.
    #[arg(long, value_parser = formats(&["text", "json", "svg", "html"]), default_value = "json")]
    pub format: Format,
    /// Write to this file instead of stdout.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

/// The flags of `batch`.
#[derive(clap::Args)]
pub struct BatchArgs {
    /// STEP files.
    #[arg(required = true)]
    pub inputs: Vec<PathBuf>,
    /// Directory for the reports and the summary.
    #[arg(long)]
    pub out: PathBuf,
    /// Parts recognized at once (default: the machine's cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Report format per part.
    #[arg(long, value_parser = formats(&["text", "json", "svg", "html"]), default_value = "json")]
    pub format: Format,
    /// Compare each part with DIR/<name>.expect.json (as `check`).
    #[arg(long)]
    pub expect: Option<PathBuf>,
    #[command(flatten)]
    pub flags: RecognizeFlags,
}

/// The flags of `check`.
#[derive(clap::Args)]
pub struct CheckArgs {
    /// The STEP file.
    pub part: PathBuf,
    /// The stored recognition (`thinwall recognize --format json`).
    #[arg(long)]
    pub expect: PathBuf,
    /// Write the part's recognition to the expectation instead.
    #[arg(long)]
    pub update: bool,
    /// Sizes within this many mm (plus the relative part) are the same.
    #[arg(allow_negative_numbers = true, long, default_value_t = 0.01)]
    pub tolerance_mm: f64,
    /// Sizes within this fraction (plus the absolute part) are the same.
    #[arg(allow_negative_numbers = true, long, default_value_t = 1e-3)]
    pub tolerance_rel: f64,
    #[command(flatten)]
    pub flags: RecognizeFlags,
}

/// The flags of `access`.
#[derive(clap::Args)]
pub struct AccessArgs {
    /// The STEP file.
    pub part: PathBuf,
    /// Up direction of the set-up (tool axis), e.g. `0,0,1`.
    #[arg(long, value_parser = parse_vector, allow_hyphen_values = true)]
    pub up: Option<[f64; 3]>,
    /// Machine class: 3-axis (tool axis = up) or 5-axis.
    #[arg(long, value_enum, default_value = "3-axis")]
    pub machine: MachineArg,
    /// 5-axis: largest tilt of the tool axis from up, degrees.
    #[arg(long, default_value_t = 30.0, allow_hyphen_values = true)]
    pub tilt_limit: f64,
    /// Tool diameter, mm: obstacles count this far above a face.
    #[arg(long, default_value_t = 12.0, allow_hyphen_values = true)]
    pub tool_diameter: f64,
    /// The tool's cutting length, mm (default three diameters).
    #[arg(long, allow_hyphen_values = true)]
    pub cutting_length: Option<f64>,
    /// The holder's diameter, mm (default two tool diameters).
    #[arg(long, allow_hyphen_values = true)]
    pub holder_diameter: Option<f64>,
    /// Widen the unreachable zones by the tool's radius.
    #[arg(long)]
    pub tool_radius: bool,
    /// Visibility ratio a face needs to be advisable.
    #[arg(long, default_value_t = 0.95, allow_hyphen_values = true)]
    pub threshold: f64,
    /// Output format.
    #[arg(long, value_parser = formats(&["text", "json", "html"]), default_value = "json")]
    pub format: Format,
    /// Write to this file instead of stdout.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

/// The flags of `operations`.
#[derive(clap::Args)]
pub struct OperationsArgs {
    /// The STEP file.
    pub part: PathBuf,
    /// Up direction of a set-up (tool axis), e.g. `0,0,1`; repeat it for
    /// set-ups in turn (`--up 0,0,1 --up 0,0,-1`), each cutting what those
    /// before it left. Default: the set-ups are proposed (the fewest ups
    /// that reach stock − part, the most material first; see --choose-up).
    #[arg(long, value_parser = parse_vector, allow_hyphen_values = true)]
    pub up: Vec<[f64; 3]>,
    /// A tool library (TOML; default: the shipped one, docs/OPERATIONS.md).
    #[arg(long)]
    pub tools: Option<PathBuf>,
    /// Depth of cut between levels, mm (default: the largest end mill's).
    #[arg(long, allow_hyphen_values = true)]
    pub axial_depth: Option<f64>,
    /// The least area, mm², an end mill must take in a cutter field of a
    /// layer to run there (default: the library's `min_share_mm2`, 20 in
    /// the shipped one); a smaller share goes to the next smaller tool or
    /// is left as rest below the minimum. 0 runs every tool that clears
    /// anything.
    #[arg(long, value_name = "MM2", allow_hyphen_values = true)]
    pub min_share: Option<f64>,
    /// Follow the plan: each machining feature of `thinwall plan`
    /// (step-approach layers, bulk) layered and tooled on its own, in
    /// an order that keeps every relation of the plan. Default: the
    /// whole removal layered at once.
    #[arg(long)]
    pub by_feature: bool,
    /// Then the set-up from the opposite side (up reversed; +Z without
    /// --up), after the first: what it cannot reach under the part (a web
    /// pocketed from both sides), its through holes and the stock round
    /// the part already gone.
    #[arg(long)]
    pub both_sides: bool,
    /// Propose the set-ups (the default without --up): the first, of the
    /// directions the part's planar faces face, the up from which the most
    /// material is reachable; then, while material is left that none
    /// reaches, the candidate that leaves the least. The ups tried and why
    /// each was taken are listed. Not with --up.
    #[arg(long, conflicts_with = "up")]
    pub choose_up: bool,
    /// Output format.
    #[arg(long, value_parser = formats(&["text", "json", "html"]), default_value = "text")]
    pub format: Format,
    /// Write to this file instead of stdout.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

/// The flags of `classify`.
#[derive(clap::Args)]
pub struct ClassifyArgs {
    /// The part (STEP).
    #[arg(long)]
    pub part: PathBuf,
    /// A volume (STEP solid); repeat for several, indexed 0, 1, … in order.
    #[arg(long, required = true)]
    pub volume: Vec<PathBuf>,
    /// `A:B`: volume A is removed before volume B (repeatable).
    #[arg(long, value_parser = parse_before)]
    pub before: Vec<(usize, usize)>,
    /// Up direction of the set-up (the tool comes from above), e.g. `0,0,1`.
    #[arg(long, value_parser = parse_vector, allow_hyphen_values = true)]
    pub up: Option<[f64; 3]>,
    /// Output format.
    #[arg(long, value_parser = formats(&["text", "json", "svg", "html"]), default_value = "json")]
    pub format: Format,
    /// Write to this file instead of stdout.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
}

#[derive(Clone, Copy, ValueEnum)]
pub enum MachineArg {
    #[value(name = "3-axis")]
    ThreeAxis,
    #[value(name = "5-axis")]
    FiveAxis,
}

/// `size-wall`: the wall and every model parameter (App. A.2 defaults).
#[derive(clap::Args)]
pub struct SizeWallArgs {
    /// Wall length, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub length: f64,
    /// Wall thickness, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub thickness: f64,
    /// Wall height, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub height: f64,
    /// Peripheral (ribs, flanges, walls) or face milling (webs).
    #[arg(long, value_enum, default_value = "peripheral")]
    pub milling: MillingArg,
    /// Preferred tool diameter, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub tool_diameter: Option<f64>,
    /// Largest milling force, N.
    #[arg(long, allow_hyphen_values = true)]
    pub force: Option<f64>,
    /// Young's modulus, N/mm².
    #[arg(long, allow_hyphen_values = true)]
    pub youngs_modulus: Option<f64>,
    /// Allowed deflection, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub allowed_deflection: Option<f64>,
    /// Effective length over wall height.
    #[arg(long, allow_hyphen_values = true)]
    pub effective_length_factor: Option<f64>,
    /// Initial H_RF / h_RF.
    #[arg(long, allow_hyphen_values = true)]
    pub initial_height_ratio: Option<f64>,
    /// Vibration re-machining zone over the tool diameter.
    #[arg(long, allow_hyphen_values = true)]
    pub zone_per_diameter: Option<f64>,
    /// Peripheral: finishing width of cut; face: finishing depth of cut, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub finishing_width: Option<f64>,
    /// Peripheral: roughing stepover over D; face: roughing depth, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub roughing_step: Option<f64>,
    /// One cut of a height, mm.
    #[arg(long, allow_hyphen_values = true)]
    pub cut_height: Option<f64>,
    /// Initial number of cuts in h_RF.
    #[arg(long)]
    pub initial_cuts: Option<u32>,
    /// Initial number of roughing steps in B_RF.
    #[arg(long)]
    pub initial_width_steps: Option<u32>,
    /// On walls higher than 4·h: largest H_RF / h_RF.
    #[arg(long, allow_hyphen_values = true)]
    pub tall_wall_max_ratio: Option<f64>,
    /// Output format.
    #[arg(long, value_parser = formats(&["text", "json"]), default_value = "json")]
    pub format: Format,
}

#[derive(Clone, Copy, ValueEnum)]
pub enum MillingArg {
    Peripheral,
    Face,
}

/// The settings flags of `recognize`.
#[derive(clap::Args)]
pub struct RecognizeFlags {
    /// Up direction of the set-up (tool axis), e.g. `0,0,1`. `plan` takes
    /// it repeated for set-ups in turn (`--up 0,0,1 --up 0,0,-1`), and
    /// without one proposes the set-ups; the others take one (default +Z).
    #[arg(long, value_parser = parse_vector, allow_hyphen_values = true)]
    pub up: Vec<[f64; 3]>,
    /// TOML file with recognition settings (see docs/RECOGNITION.md).
    #[arg(long)]
    pub config: Option<PathBuf>,
    /// Only report these kinds (comma separated).
    #[arg(long, value_delimiter = ',')]
    pub include: Vec<String>,
    /// Never report these kinds (comma separated).
    #[arg(long, value_delimiter = ',')]
    pub exclude: Vec<String>,
    /// Maximum milling force, N.
    #[arg(allow_negative_numbers = true, long)]
    pub force: Option<f64>,
    /// Allowed deflection, mm.
    #[arg(allow_negative_numbers = true, long)]
    pub allowed_deflection: Option<f64>,
    /// Preferred tool diameter, mm.
    #[arg(allow_negative_numbers = true, long)]
    pub tool_diameter: Option<f64>,
    /// Machine class: 3-axis (tool axis = up) or 5-axis.
    #[arg(long, value_enum, default_value = "3-axis")]
    pub machine: MachineArg,
    /// 5-axis: largest tilt of the tool axis from up, degrees.
    #[arg(allow_negative_numbers = true, long, default_value_t = 30.0)]
    pub tilt_limit: f64,
    /// Link thin walls to the thick walls they stand on.
    #[arg(long)]
    pub connect_thick: bool,
    /// Recognize a part whose shell is open (edges used by one face only)
    /// instead of refusing it.
    #[arg(long)]
    pub allow_open: bool,
    /// The stock the part is cut from: a STEP solid (a blank, a casting
    /// envelope). Faces on its surface are not machined.
    #[arg(long, conflicts_with = "stock_offset")]
    pub stock: Option<PathBuf>,
    /// A uniform allowance on the part's block, mm: its faces on the block
    /// are faced.
    #[arg(long, allow_hyphen_values = true)]
    pub stock_offset: Option<f64>,
    /// Reach of wall sides: the tool's cutting length, mm (default three
    /// diameters of the preferred tool).
    #[arg(long, allow_hyphen_values = true)]
    pub cutting_length: Option<f64>,
    /// Reach of wall sides: the holder's diameter, mm (default two
    /// diameters).
    #[arg(long, allow_hyphen_values = true)]
    pub holder_diameter: Option<f64>,
    /// Judge wall sides by direction only, not by what is in the way.
    #[arg(long)]
    pub no_reach: bool,
}

impl RecognizeFlags {
    /// The request: the settings file (if any), then the flags over it.
    /// One `--up` at most.
    pub fn request(self) -> Result<thinwall_study::RecognizeRequest, Failure> {
        if self.up.len() > 1 {
            return Err(Failure::Usage(
                "--up: one set-up here (only plan takes several, in turn)".into(),
            ));
        }
        self.first_request()
    }

    /// The request of the first `--up` and the ups after it (set-ups in
    /// turn, `plan`).
    pub fn in_turn(mut self) -> Result<(thinwall_study::RecognizeRequest, Vec<[f64; 3]>), Failure> {
        let later = self.up.split_off(self.up.len().min(1));
        Ok((self.first_request()?, later))
    }

    fn first_request(self) -> Result<thinwall_study::RecognizeRequest, Failure> {
        let settings = match &self.config {
            Some(path) => {
                // A settings file that cannot be used is a usage failure,
                // however it fails (missing, unreadable, not UTF-8, bad TOML).
                let text = std::fs::read_to_string(path)
                    .map_err(|e| Failure::Usage(format!("--config: {}: {e}", path.display())))?;
                thinwall_pipeline::Settings::from_toml(&text, &path.display().to_string())
                    .map_err(Failure::usage)?
            }
            None => thinwall_pipeline::Settings::default(),
        };
        let mut cfg = settings.config;
        for (list, names) in [
            (&mut cfg.include, &self.include),
            (&mut cfg.exclude, &self.exclude),
        ] {
            for n in names.iter().filter(|n| !n.is_empty()) {
                list.push(
                    thinwall_analysis::StiffnessKind::parse(n)
                        .ok_or_else(|| Failure::Usage(format!("unknown feature kind '{n}'")))?,
                );
            }
        }
        if let Some(f) = self.force {
            cfg.thinness.force_n = f;
        }
        if let Some(d) = self.allowed_deflection {
            cfg.thinness.allowed_deflection_mm = d;
        }
        if let Some(d) = self.tool_diameter {
            cfg.thresholds.preferred_tool_diameter_mm = d;
        }
        let given_up = self.up.first().copied().or(settings.up);
        let setup = thinwall_study::setup_of(given_up, self.machine.machine(self.tilt_limit))?;
        let stock = match &self.stock {
            Some(path) => Some(std::sync::Arc::new(thinwall_step::read_file(path)?.0)),
            None => None,
        };
        let reach_tool = (!self.no_reach).then(|| {
            tool(
                cfg.thresholds.preferred_tool_diameter_mm,
                self.cutting_length,
                self.holder_diameter,
            )
        });
        let request = thinwall_study::RecognizeRequest {
            reach_tool,
            setup,
            config: cfg,
            connect: thinwall_connect::Options {
                connect_thick_walls: self.connect_thick,
            },
            parallel: true,
            allow_open: self.allow_open,
            machining: thinwall_pipeline::MachiningRequest {
                in_setup: given_up.is_some(),
                stock_offset: self.stock_offset.unwrap_or(0.0),
                stock,
                stock_file: self.stock.as_ref().map(|p| p.display().to_string()),
            },
        };
        request
            .check()
            .map_err(|e| Failure::from(thinwall_study::StudyError::Request(e)))?;
        Ok(request)
    }
}

impl MachineArg {
    /// The machine, with `tilt_limit` when it is a 5-axis one.
    pub fn machine(self, tilt_limit: f64) -> thinwall_analysis::Machine {
        match self {
            MachineArg::ThreeAxis => thinwall_analysis::Machine::ThreeAxis,
            MachineArg::FiveAxis => thinwall_analysis::Machine::FiveAxis {
                tilt_limit_deg: tilt_limit,
            },
        }
    }
}

/// A tool of `diameter` with the flags over its proportions (checked by
/// the request that carries it).
pub fn tool(
    diameter: f64,
    cutting_length: Option<f64>,
    holder_diameter: Option<f64>,
) -> thinwall_access::reach::Tool {
    let mut tool = thinwall_access::reach::Tool::new(diameter);
    if let Some(l) = cutting_length {
        tool.cutting_length = l;
    }
    if let Some(h) = holder_diameter {
        tool.holder_diameter = h;
    }
    tool
}

pub fn parse_vector(s: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!("expected X,Y,Z, got '{s}'"));
    }
    let mut v = [0.0f64; 3];
    for (i, p) in parts.iter().enumerate() {
        v[i] = p.parse().map_err(|_| format!("'{p}' is not a number"))?;
    }
    // Whether it is a direction (not zero, finite) is the set-up's rule.
    Ok(v)
}

impl SizeWallArgs {
    /// The request: App. A.2's defaults for the milling, the flags over them.
    pub fn request(&self) -> thinwall_study::SizeWallRequest {
        use thinwall_plan::sizing::{Milling, SizingParameters, WallDimensions};
        let milling = match self.milling {
            MillingArg::Peripheral => Milling::Peripheral,
            MillingArg::Face => Milling::Face,
        };
        let mut p = SizingParameters::defaults(milling);
        if let Some(d) = self.tool_diameter {
            p.tool_diameter_mm = d;
            if milling == Milling::Face {
                p.cut_height_mm = 0.5 * d + 1.0;
            }
        }
        let set = |slot: &mut f64, v: Option<f64>| {
            if let Some(v) = v {
                *slot = v;
            }
        };
        set(&mut p.force_n, self.force);
        set(&mut p.youngs_modulus_n_mm2, self.youngs_modulus);
        set(&mut p.allowed_deflection_mm, self.allowed_deflection);
        set(&mut p.effective_length_factor, self.effective_length_factor);
        set(&mut p.initial_height_ratio, self.initial_height_ratio);
        set(&mut p.zone_per_diameter, self.zone_per_diameter);
        set(&mut p.finishing_width_mm, self.finishing_width);
        set(&mut p.roughing_step, self.roughing_step);
        set(&mut p.cut_height_mm, self.cut_height);
        set(&mut p.tall_wall_max_ratio, self.tall_wall_max_ratio);
        if let Some(n) = self.initial_cuts {
            p.initial_cuts = n;
        }
        if let Some(n) = self.initial_width_steps {
            p.initial_width_steps = n;
        }
        thinwall_study::SizeWallRequest {
            wall: WallDimensions {
                length: self.length,
                thickness: self.thickness,
                height: self.height,
            },
            parameters: p,
        }
    }
}
