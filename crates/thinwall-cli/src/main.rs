//! `thinwall`: look at a STEP part the way a process planner for thin-walled
//! parts does.

use clap::{Parser, Subcommand, ValueEnum};
use std::io::Write;
use std::path::PathBuf;
use std::process::ExitCode;
use thinwall_graph::AdjacencyGraph;

mod batch;
mod check;
mod failure;
mod operations;
mod render;
use failure::Failure;

#[derive(Parser)]
#[command(
    name = "thinwall",
    version,
    about = "Stiffness features and machining features of thin-walled parts, from STEP"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Clone, Copy, ValueEnum)]
enum Format {
    Text,
    Json,
}

/// `access`'s and `operations`' formats: also a page.
#[derive(Clone, Copy, ValueEnum)]
enum AccessFormat {
    Text,
    Json,
    /// One self-contained page: faces coloured by how much is reached.
    Html,
}

/// `plan`'s and `classify`'s formats: also a picture and a page.
#[derive(Clone, Copy, ValueEnum)]
enum PageFormat {
    Text,
    Json,
    /// An isometric picture of the part and the volumes, with a legend.
    Svg,
    /// One self-contained page: a 3D view with the volumes.
    Html,
}

#[derive(Subcommand)]
enum Command {
    /// Read a part and report its bodies, faces, edges and their convexity.
    Inspect {
        /// The STEP file (AP203, AP214 or AP242).
        part: PathBuf,
        /// Output format.
        #[arg(long, value_enum, default_value = "text")]
        format: Format,
    },
    /// Recognize stiffness features: walls (web, rib, flange), thinness,
    /// holes, cut-outs, notches, fillets, chamfers.
    Recognize {
        /// The STEP file.
        part: PathBuf,
        #[command(flatten)]
        flags: RecognizeFlags,
        /// Print the time of every stage and every warning to stderr.
        #[arg(long)]
        verbose: bool,
        /// Output format.
        #[arg(long, value_enum, default_value = "json")]
        format: render::RecognitionFormat,
        /// Write to this file instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Plan the machining order of the stiffness features: sequence
    /// constraints from rules (docs/PLANNING.md), each decision explained.
    Plan {
        /// The STEP file.
        part: PathBuf,
        #[command(flatten)]
        flags: RecognizeFlags,
        /// A TOML file of sequence rules (default: the shipped five).
        #[arg(long)]
        rules: Option<PathBuf>,
        /// Write each step-approach layer as a STEP solid (`V1.step`, …) here.
        #[arg(long)]
        volumes_dir: Option<PathBuf>,
        /// Output format.
        #[arg(long, value_enum, default_value = "json")]
        format: PageFormat,
        /// Write to this file instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Recognize many parts in parallel: one report per part in OUT, a
    /// summary (summary.jsonl and a table), progress on stderr. A bad file
    /// is reported, not fatal; exit 1 when any part failed.
    Batch {
        /// STEP files.
        #[arg(required = true)]
        inputs: Vec<PathBuf>,
        /// Directory for the reports and the summary.
        #[arg(long)]
        out: PathBuf,
        /// Parts recognized at once (default: the machine's cores).
        #[arg(long)]
        jobs: Option<usize>,
        /// Report format per part.
        #[arg(long, value_enum, default_value = "json")]
        format: batch::BatchFormat,
        /// Compare each part with DIR/<name>.expect.json (as `check`).
        #[arg(long)]
        expect: Option<PathBuf>,
        #[command(flatten)]
        flags: RecognizeFlags,
    },
    /// Compare a part's recognition with a stored one (a regression check
    /// of your own parts): features added, lost, changed kind or size,
    /// thinness, connections. Exit 1 on any difference.
    Check {
        /// The STEP file.
        part: PathBuf,
        /// The stored recognition (`thinwall recognize --format json`).
        #[arg(long)]
        expect: PathBuf,
        /// Write the part's recognition to the expectation instead.
        #[arg(long)]
        update: bool,
        /// Sizes within this many mm (plus the relative part) are the same.
        #[arg(long, default_value_t = 0.01)]
        tolerance_mm: f64,
        /// Sizes within this fraction (plus the absolute part) are the same.
        #[arg(long, default_value_t = 1e-3)]
        tolerance_rel: f64,
        #[command(flatten)]
        flags: RecognizeFlags,
    },
    /// Accessibility of the part's faces: how much of each face and wall
    /// side a tool and its holder reach with material in the way, and
    /// whether each planar face can be flank milled (its G-zone, Harik &
    /// Ris; docs/ACCESS.md).
    Access {
        /// The STEP file.
        part: PathBuf,
        /// Up direction of the set-up (tool axis), e.g. `0,0,1`.
        #[arg(long, value_parser = parse_vector, allow_hyphen_values = true)]
        up: Option<[f64; 3]>,
        /// Machine class: 3-axis (tool axis = up) or 5-axis.
        #[arg(long, value_enum, default_value = "3-axis")]
        machine: MachineArg,
        /// 5-axis: largest tilt of the tool axis from up, degrees.
        #[arg(long, default_value_t = 30.0, allow_hyphen_values = true)]
        tilt_limit: f64,
        /// Tool diameter, mm: obstacles count this far above a face.
        #[arg(long, default_value_t = 12.0, allow_hyphen_values = true)]
        tool_diameter: f64,
        /// The tool's cutting length, mm (default three diameters).
        #[arg(long, allow_hyphen_values = true)]
        cutting_length: Option<f64>,
        /// The holder's diameter, mm (default two tool diameters).
        #[arg(long, allow_hyphen_values = true)]
        holder_diameter: Option<f64>,
        /// Widen the unreachable zones by the tool's radius.
        #[arg(long)]
        tool_radius: bool,
        /// Visibility ratio a face needs to be advisable.
        #[arg(long, default_value_t = 0.95, allow_hyphen_values = true)]
        threshold: f64,
        /// Output format.
        #[arg(long, value_enum, default_value = "json")]
        format: AccessFormat,
        /// Write to this file instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Operations of a set-up: layers from the stock's top (and at every
    /// flat face), cutter fields, the largest tools that fit with their
    /// rest areas and regions (boundary, full cut, roughing), floors'
    /// finishing, holes drilled by subtype, in an order that cuts tool
    /// changes (docs/OPERATIONS.md).
    Operations {
        /// The STEP file.
        part: PathBuf,
        /// Up direction of the set-up (tool axis), e.g. `0,0,1`.
        #[arg(long, value_parser = parse_vector, allow_hyphen_values = true)]
        up: Option<[f64; 3]>,
        /// A tool library (TOML; default: the shipped one, docs/OPERATIONS.md).
        #[arg(long)]
        tools: Option<PathBuf>,
        /// Depth of cut between levels, mm (default: the largest end mill's).
        #[arg(long, allow_hyphen_values = true)]
        axial_depth: Option<f64>,
        /// Follow the plan: each machining feature of `thinwall plan`
        /// (step-approach layers, bulk) layered and tooled on its own, in
        /// an order that keeps every relation of the plan. Default: the
        /// whole removal layered at once.
        #[arg(long)]
        by_feature: bool,
        /// Output format.
        #[arg(long, value_enum, default_value = "text")]
        format: AccessFormat,
        /// Write to this file instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Size a thin wall's machining features (B_RF, h_RF, H_RF) with the
    /// step-approach bending model (docs/PLANNING.md).
    SizeWall(SizeWallArgs),
    /// Classify machining-feature volumes (pocket, slot, step, …) by shape
    /// and by which faces touch the part or volumes not removed before them.
    Classify {
        /// The part (STEP).
        #[arg(long)]
        part: PathBuf,
        /// A volume (STEP solid); repeat for several, indexed 0, 1, … in order.
        #[arg(long, required = true)]
        volume: Vec<PathBuf>,
        /// `A:B`: volume A is removed before volume B (repeatable).
        #[arg(long, value_parser = parse_before)]
        before: Vec<(usize, usize)>,
        /// Up direction of the set-up (the tool comes from above), e.g. `0,0,1`.
        #[arg(long, value_parser = parse_vector, allow_hyphen_values = true)]
        up: Option<[f64; 3]>,
        /// Output format.
        #[arg(long, value_enum, default_value = "json")]
        format: PageFormat,
        /// Write to this file instead of stdout.
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
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

#[derive(Clone, Copy, ValueEnum)]
enum MachineArg {
    #[value(name = "3-axis")]
    ThreeAxis,
    #[value(name = "5-axis")]
    FiveAxis,
}

/// `size-wall`: the wall and every model parameter (App. A.2 defaults).
#[derive(clap::Args)]
struct SizeWallArgs {
    /// Wall length, mm.
    #[arg(long, allow_hyphen_values = true)]
    length: f64,
    /// Wall thickness, mm.
    #[arg(long, allow_hyphen_values = true)]
    thickness: f64,
    /// Wall height, mm.
    #[arg(long, allow_hyphen_values = true)]
    height: f64,
    /// Peripheral (ribs, flanges, walls) or face milling (webs).
    #[arg(long, value_enum, default_value = "peripheral")]
    milling: MillingArg,
    /// Preferred tool diameter, mm.
    #[arg(long, allow_hyphen_values = true)]
    tool_diameter: Option<f64>,
    /// Largest milling force, N.
    #[arg(long, allow_hyphen_values = true)]
    force: Option<f64>,
    /// Young's modulus, N/mm².
    #[arg(long, allow_hyphen_values = true)]
    youngs_modulus: Option<f64>,
    /// Allowed deflection, mm.
    #[arg(long, allow_hyphen_values = true)]
    allowed_deflection: Option<f64>,
    /// Effective length over wall height.
    #[arg(long, allow_hyphen_values = true)]
    effective_length_factor: Option<f64>,
    /// Initial H_RF / h_RF.
    #[arg(long, allow_hyphen_values = true)]
    initial_height_ratio: Option<f64>,
    /// Vibration re-machining zone over the tool diameter.
    #[arg(long, allow_hyphen_values = true)]
    zone_per_diameter: Option<f64>,
    /// Peripheral: finishing width of cut; face: finishing depth of cut, mm.
    #[arg(long, allow_hyphen_values = true)]
    finishing_width: Option<f64>,
    /// Peripheral: roughing stepover over D; face: roughing depth, mm.
    #[arg(long, allow_hyphen_values = true)]
    roughing_step: Option<f64>,
    /// One cut of a height, mm.
    #[arg(long, allow_hyphen_values = true)]
    cut_height: Option<f64>,
    /// Initial number of cuts in h_RF.
    #[arg(long)]
    initial_cuts: Option<u32>,
    /// Initial number of roughing steps in B_RF.
    #[arg(long)]
    initial_width_steps: Option<u32>,
    /// On walls higher than 4·h: largest H_RF / h_RF.
    #[arg(long, allow_hyphen_values = true)]
    tall_wall_max_ratio: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value = "json")]
    format: Format,
}

#[derive(Clone, Copy, ValueEnum)]
enum MillingArg {
    Peripheral,
    Face,
}

fn size_wall_command(a: SizeWallArgs) -> Result<(), Failure> {
    use thinwall_plan::sizing::{size_wall, Milling, SizingParameters, WallDimensions};
    let milling = match a.milling {
        MillingArg::Peripheral => Milling::Peripheral,
        MillingArg::Face => Milling::Face,
    };
    let mut p = SizingParameters::defaults(milling);
    if let Some(d) = a.tool_diameter {
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
    set(&mut p.force_n, a.force);
    set(&mut p.youngs_modulus_n_mm2, a.youngs_modulus);
    set(&mut p.allowed_deflection_mm, a.allowed_deflection);
    set(&mut p.effective_length_factor, a.effective_length_factor);
    set(&mut p.initial_height_ratio, a.initial_height_ratio);
    set(&mut p.zone_per_diameter, a.zone_per_diameter);
    set(&mut p.finishing_width_mm, a.finishing_width);
    set(&mut p.roughing_step, a.roughing_step);
    set(&mut p.cut_height_mm, a.cut_height);
    set(&mut p.tall_wall_max_ratio, a.tall_wall_max_ratio);
    if let Some(n) = a.initial_cuts {
        p.initial_cuts = n;
    }
    if let Some(n) = a.initial_width_steps {
        p.initial_width_steps = n;
    }
    let w = WallDimensions {
        length: a.length,
        thickness: a.thickness,
        height: a.height,
    };
    let sizes = size_wall(&w, &p).map_err(|e| Failure::Usage(e.to_string()))?;
    write_out(&match a.format {
        Format::Json => serde_json::to_string_pretty(&sizes).expect("sizes serialise") + "\n",
        Format::Text => sizes.to_text(),
    })
}

fn plan_command(
    part: PathBuf,
    flags: RecognizeFlags,
    rules: Option<PathBuf>,
    volumes_dir: Option<PathBuf>,
    format: PageFormat,
    output: Option<PathBuf>,
) -> Result<(), Failure> {
    let rules = match &rules {
        Some(path) => {
            let text = std::fs::read_to_string(path)
                .map_err(|e| Failure::Input(format!("{}: {e}", path.display())))?;
            thinwall_plan::RuleSet::from_toml(&text, &path.display().to_string())
                .map_err(|e| Failure::Usage(e.to_string()))?
        }
        None => thinwall_plan::RuleSet::default_rules(),
    };
    let request = flags.request()?;
    let (model, _) = thinwall_step::read_file(&part)?;
    let outcome = thinwall_pipeline::run(&model, None, &request)
        .map_err(|e| Failure::from(e).in_file(&part))?;
    let plan = thinwall_plan::plan(&part.display().to_string(), &model, &outcome, &rules);
    if let Some(dir) = &volumes_dir {
        std::fs::create_dir_all(dir)
            .map_err(|e| Failure::Input(format!("{}: {e}", dir.display())))?;
        let mut skipped = 0;
        for f in &plan.machining_features {
            let path = dir.join(format!("{}.step", f.id));
            let (text, missing) = thinwall_plan::volumes::feature_step(&plan, f);
            skipped += missing;
            if missing == f.solids.len() {
                continue;
            }
            std::fs::write(&path, text)
                .map_err(|e| Failure::Input(format!("{}: {e}", path.display())))?;
        }
        if skipped > 0 {
            eprintln!(
                "note: {skipped} solid(s) bounded by a cylinder or cone are not written yet (their volumes are in the plan)"
            );
        }
    }
    let text = match format {
        PageFormat::Text => plan.to_text(),
        PageFormat::Json => plan.to_json(),
        PageFormat::Svg | PageFormat::Html => {
            let report =
                thinwall_report::recognition_report(&part.display().to_string(), &model, &outcome);
            let a = thinwall_analysis::PartAnalysis::new(&model, outcome.setup.clone());
            let title = format!("Plan: {}", part.display());
            match format {
                PageFormat::Svg => thinwall_report::svg::plan_picture(
                    &a,
                    &thinwall_brep::tessellate::part_mesh(&model),
                    &report.stiffness_features,
                    &plan,
                    &title,
                    1000.0,
                ),
                _ => thinwall_report::html::plan_page(&title, &a, &report, &plan),
            }
        }
    };
    write_to(output.as_deref(), &text)
}

fn classify_command(
    part: PathBuf,
    volume: Vec<PathBuf>,
    before: Vec<(usize, usize)>,
    up: Option<[f64; 3]>,
    format: PageFormat,
    output: Option<PathBuf>,
) -> Result<(), Failure> {
    let (model, _) = thinwall_step::read_file(&part)?;
    let mut volumes = Vec::new();
    for v in &volume {
        let (p, _) = thinwall_step::read_file(v)?;
        volumes.push(thinwall_classify::Volume {
            name: v.display().to_string(),
            part: p,
            current: None,
            up: None,
        });
    }
    let setup = thinwall_analysis::Setup::new(
        up.unwrap_or([0.0, 0.0, 1.0]),
        thinwall_analysis::Machine::ThreeAxis,
    )
    .map_err(Failure::usage)?;
    let analysis = thinwall_analysis::PartAnalysis::new(&model, setup.clone());
    let result = thinwall_classify::classify(&thinwall_classify::Request {
        part: &analysis,
        volumes: &volumes,
        before: &before,
        together: &[],
        priority: vec![],
    })?;
    let report = thinwall_report::ClassificationReport::new(
        &part.display().to_string(),
        setup.up,
        &before,
        result,
    );
    let text = match format {
        PageFormat::Text => report.to_text(),
        PageFormat::Json => report.to_json(),
        PageFormat::Svg | PageFormat::Html => {
            let parts: Vec<&thinwall_brep::Part> = volumes.iter().map(|v| &v.part).collect();
            let title = format!("Classification: {}", part.display());
            match format {
                PageFormat::Svg => thinwall_report::svg::classification_picture(
                    &analysis, &report, &parts, &title, 1000.0,
                ),
                _ => thinwall_report::html::classification_page(&title, &analysis, &report, &parts),
            }
        }
    };
    write_to(output.as_deref(), &text)
}

/// What `access` judges reach with.
struct ReachArgs {
    machine: thinwall_analysis::Machine,
    cutting_length: Option<f64>,
    holder_diameter: Option<f64>,
}

fn access_command(
    part: PathBuf,
    up: Option<[f64; 3]>,
    options: thinwall_access::FlankOptions,
    reach: ReachArgs,
    format: AccessFormat,
    output: Option<PathBuf>,
) -> Result<(), Failure> {
    if !(options.tool_diameter.is_finite() && options.tool_diameter > 0.0) {
        return Err(Failure::Usage(format!(
            "--tool-diameter must be a positive length, got {}",
            options.tool_diameter
        )));
    }
    if !(0.0..=1.0).contains(&options.threshold) {
        return Err(Failure::Usage(format!(
            "--threshold must lie between 0 and 1, got {}",
            options.threshold
        )));
    }
    let tool = reach_tool(
        options.tool_diameter,
        reach.cutting_length,
        reach.holder_diameter,
    )?;
    if let thinwall_analysis::Machine::FiveAxis { tilt_limit_deg } = reach.machine {
        if !(tilt_limit_deg.is_finite() && (0.0..90.0).contains(&tilt_limit_deg)) {
            return Err(Failure::Usage(format!(
                "--tilt-limit must be within 0..90 degrees, got {tilt_limit_deg}"
            )));
        }
    }
    let (model, _) = thinwall_step::read_file(&part)?;
    let setup = thinwall_analysis::Setup::new(up.unwrap_or([0.0, 0.0, 1.0]), reach.machine)
        .map_err(Failure::usage)?;
    let a = thinwall_analysis::PartAnalysis::new(&model, setup.clone());
    let mesh = thinwall_brep::tessellate::part_mesh(&model);
    let faces = thinwall_access::flank_milling(&a, &mesh, &options);
    let reach_opts = thinwall_access::reach::ReachOptions {
        tool: tool.clone(),
        machine: reach.machine,
        largest_tool: true,
    };
    // Every face with largest tools takes minutes on large parts: a bar
    // on a terminal.
    let bar = std::io::IsTerminal::is_terminal(&std::io::stderr()).then(|| {
        let b = indicatif::ProgressBar::new(mesh.faces.len() as u64);
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "reach {bar:40} {pos}/{len} faces, {elapsed} ({eta} left)",
        ) {
            b.set_style(style);
        }
        b
    });
    let reached = thinwall_access::reach::reach_observed(
        &a,
        &mesh,
        &reach_opts,
        |_| true,
        |_, _| {
            if let Some(b) = &bar {
                b.inc(1);
            }
        },
    )
    .map_err(|e| Failure::Usage(e.to_string()))?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    // The walls, for their sides: the recognizer's, without its own reach.
    let request = thinwall_pipeline::Request {
        setup: setup.clone(),
        allow_open: true,
        ..Default::default()
    };
    let outcome = thinwall_pipeline::run(&model, None, &request)?;
    let reach_result =
        thinwall_report::access::ReachResult::new(&a, reached, &outcome, tool.diameter);
    let report = thinwall_report::access::AccessReport::new(
        &part.display().to_string(),
        setup.up,
        options,
        faces,
        thinwall_report::access::ReachSettings {
            tool,
            machine: reach.machine,
        },
        reach_result,
    );
    let text = match format {
        AccessFormat::Text => report.to_text(),
        AccessFormat::Json => report.to_json(),
        AccessFormat::Html => {
            thinwall_report::html::access_page(&format!("Access: {}", part.display()), &a, &report)
        }
    };
    write_to(output.as_deref(), &text)
}

fn parse_vector(s: &str) -> Result<[f64; 3], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != 3 {
        return Err(format!("expected X,Y,Z, got '{s}'"));
    }
    let mut v = [0.0f64; 3];
    for (i, p) in parts.iter().enumerate() {
        v[i] = p.parse().map_err(|_| format!("'{p}' is not a number"))?;
    }
    if v.iter().all(|c| *c == 0.0) || v.iter().any(|c| !c.is_finite()) {
        return Err(format!("'{s}' is not a direction"));
    }
    Ok(v)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(failure) => {
            eprintln!("thinwall: error: {}", failure.message());
            ExitCode::from(failure.exit_code())
        }
    }
}

fn run(cli: Cli) -> Result<(), Failure> {
    match cli.command {
        Command::Classify {
            part,
            volume,
            before,
            up,
            format,
            output,
        } => classify_command(part, volume, before, up, format, output),
        Command::Plan {
            part,
            flags,
            rules,
            volumes_dir,
            format,
            output,
        } => plan_command(part, flags, rules, volumes_dir, format, output),
        Command::SizeWall(args) => size_wall_command(args),
        Command::Access {
            part,
            up,
            machine,
            tilt_limit,
            tool_diameter,
            cutting_length,
            holder_diameter,
            tool_radius,
            threshold,
            format,
            output,
        } => {
            let options = thinwall_access::FlankOptions {
                tool_diameter,
                tool_radius,
                threshold,
            };
            let machine = match machine {
                MachineArg::ThreeAxis => thinwall_analysis::Machine::ThreeAxis,
                MachineArg::FiveAxis => thinwall_analysis::Machine::FiveAxis {
                    tilt_limit_deg: tilt_limit,
                },
            };
            let reach = ReachArgs {
                machine,
                cutting_length,
                holder_diameter,
            };
            access_command(part, up, options, reach, format, output)
        }
        Command::Operations {
            part,
            up,
            tools,
            axial_depth,
            by_feature,
            format,
            output,
        } => {
            let text = operations::run(operations::OperationsArgs {
                part,
                up,
                tools,
                axial_depth,
                by_feature,
                format: match format {
                    AccessFormat::Text => operations::OpsFormat::Text,
                    AccessFormat::Json => operations::OpsFormat::Json,
                    AccessFormat::Html => operations::OpsFormat::Html,
                },
            })?;
            write_to(output.as_deref(), &text)
        }
        Command::Batch {
            inputs,
            out,
            jobs,
            format,
            expect,
            flags,
        } => {
            let mut request = flags.request()?;
            // The parts run in parallel; each runs alone.
            request.parallel = false;
            batch::command(batch::Batch {
                inputs,
                out,
                jobs: jobs
                    .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get())),
                format,
                expect,
                request,
            })
        }
        Command::Check {
            part,
            expect,
            update,
            tolerance_mm,
            tolerance_rel,
            flags,
        } => check::command(
            &part,
            &expect,
            update,
            thinwall_report::expect::CheckTolerance {
                absolute_mm: tolerance_mm,
                relative: tolerance_rel,
            },
            flags.request()?,
        ),
        Command::Inspect { part, format } => {
            let (model, read) = thinwall_step::read_file(&part)?;
            let graph = AdjacencyGraph::build(&model, &model.tolerances());
            let report =
                thinwall_report::inspect(&part.display().to_string(), &model, &read, &graph);
            write_out(&match format {
                Format::Text => report.to_text(),
                Format::Json => report.to_json(),
            })
        }
        Command::Recognize {
            part,
            flags,
            verbose,
            format,
            output,
        } => {
            let request = flags.request()?;
            let t0 = std::time::Instant::now();
            let (model, read) = thinwall_step::read_file(&part)?;
            let read_seconds = t0.elapsed().as_secs_f64();
            let outcome = thinwall_pipeline::run(&model, None, &request)
                .map_err(|e| Failure::from(e).in_file(&part))?;
            let report =
                thinwall_report::recognition_report(&part.display().to_string(), &model, &outcome)
                    .with_read(&read);
            if verbose {
                eprintln!("{:>9.4} s  read", read_seconds);
                for (stage, seconds) in &outcome.timings {
                    eprintln!("{seconds:>9.4} s  {stage}");
                }
                for w in &report.warnings {
                    eprintln!("warning: {}", w.message);
                }
            }
            let title = part.display().to_string();
            let text = render::recognition(format, &model, &outcome, &report, &title);
            write_to(output.as_deref(), &text)
        }
    }
}

/// The settings flags of `recognize`.
#[derive(clap::Args)]
struct RecognizeFlags {
    /// Up direction of the set-up (tool axis), e.g. `0,0,1`.
    #[arg(long, value_parser = parse_vector, allow_hyphen_values = true)]
    up: Option<[f64; 3]>,
    /// TOML file with recognition settings (see docs/RECOGNITION.md).
    #[arg(long)]
    config: Option<PathBuf>,
    /// Only report these kinds (comma separated).
    #[arg(long, value_delimiter = ',')]
    include: Vec<String>,
    /// Never report these kinds (comma separated).
    #[arg(long, value_delimiter = ',')]
    exclude: Vec<String>,
    /// Maximum milling force, N.
    #[arg(long)]
    force: Option<f64>,
    /// Allowed deflection, mm.
    #[arg(long)]
    allowed_deflection: Option<f64>,
    /// Preferred tool diameter, mm.
    #[arg(long)]
    tool_diameter: Option<f64>,
    /// Machine class: 3-axis (tool axis = up) or 5-axis.
    #[arg(long, value_enum, default_value = "3-axis")]
    machine: MachineArg,
    /// 5-axis: largest tilt of the tool axis from up, degrees.
    #[arg(long, default_value_t = 30.0)]
    tilt_limit: f64,
    /// Link thin walls to the thick walls they stand on.
    #[arg(long)]
    connect_thick: bool,
    /// Recognize a part whose shell is open (edges used by one face only)
    /// instead of refusing it.
    #[arg(long)]
    allow_open: bool,
    /// The stock the part is cut from: a STEP solid (a blank, a casting
    /// envelope). Faces on its surface are not machined.
    #[arg(long, conflicts_with = "stock_offset")]
    stock: Option<PathBuf>,
    /// A uniform allowance on the part's block, mm: its faces on the block
    /// are faced.
    #[arg(long, allow_hyphen_values = true)]
    stock_offset: Option<f64>,
    /// Reach of wall sides: the tool's cutting length, mm (default three
    /// diameters of the preferred tool).
    #[arg(long, allow_hyphen_values = true)]
    cutting_length: Option<f64>,
    /// Reach of wall sides: the holder's diameter, mm (default two
    /// diameters).
    #[arg(long, allow_hyphen_values = true)]
    holder_diameter: Option<f64>,
    /// Judge wall sides by direction only, not by what is in the way.
    #[arg(long)]
    no_reach: bool,
}

impl RecognizeFlags {
    /// The request: the settings file (if any), then the flags over it.
    fn request(self) -> Result<thinwall_pipeline::Request, Failure> {
        let settings = match &self.config {
            Some(path) => {
                let text = std::fs::read_to_string(path)
                    .map_err(|e| Failure::Input(format!("{}: {e}", path.display())))?;
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
        cfg.validate().map_err(Failure::usage)?;
        if !(self.tilt_limit.is_finite() && (0.0..=90.0).contains(&self.tilt_limit)) {
            return Err(Failure::Usage(format!(
                "--tilt-limit must be within 0..90 degrees, got {}",
                self.tilt_limit
            )));
        }
        let machine = match self.machine {
            MachineArg::ThreeAxis => thinwall_analysis::Machine::ThreeAxis,
            MachineArg::FiveAxis => thinwall_analysis::Machine::FiveAxis {
                tilt_limit_deg: self.tilt_limit,
            },
        };
        let given_up = self.up.or(settings.up);
        let up = given_up.unwrap_or([0.0, 0.0, 1.0]);
        let setup = thinwall_analysis::Setup::new(up, machine).map_err(Failure::usage)?;
        let stock = match &self.stock {
            Some(path) => {
                let (solid, _) = thinwall_step::read_file(path).map_err(Failure::from)?;
                Some(std::sync::Arc::new(solid))
            }
            None => None,
        };
        let stock_offset = self.stock_offset.unwrap_or(0.0);
        if !(stock_offset.is_finite() && stock_offset >= 0.0) {
            return Err(Failure::Usage(format!(
                "--stock-offset must be a length of 0 mm or more, got {stock_offset}"
            )));
        }
        let reach_tool = (!self.no_reach)
            .then(|| {
                reach_tool(
                    cfg.thresholds.preferred_tool_diameter_mm,
                    self.cutting_length,
                    self.holder_diameter,
                )
            })
            .transpose()?;
        Ok(thinwall_pipeline::Request {
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
                stock_offset,
                stock,
                stock_file: self.stock.as_ref().map(|p| p.display().to_string()),
            },
        })
    }
}

/// The reach tool from a diameter and the flags over its proportions,
/// checked.
fn reach_tool(
    diameter: f64,
    cutting_length: Option<f64>,
    holder_diameter: Option<f64>,
) -> Result<thinwall_access::reach::Tool, Failure> {
    let mut tool = thinwall_access::reach::Tool::new(diameter);
    if let Some(l) = cutting_length {
        tool.cutting_length = l;
    }
    if let Some(h) = holder_diameter {
        tool.holder_diameter = h;
    }
    tool.check().map_err(|e| Failure::Usage(e.to_string()))?;
    Ok(tool)
}

/// Write to `path`, or to stdout without one.
fn write_to(path: Option<&std::path::Path>, text: &str) -> Result<(), Failure> {
    match path {
        Some(path) => std::fs::write(path, text)
            .map_err(|e| Failure::Input(format!("{}: {e}", path.display()))),
        None => write_out(text),
    }
}

fn write_out(text: &str) -> Result<(), Failure> {
    std::io::stdout()
        .write_all(text.as_bytes())
        .map_err(|e| Failure::Input(format!("cannot write output: {e}")))
}
