//! The command line of `tmm`: its commands, their flags and values (clap).

use clap::{Parser, Subcommand, ValueEnum};
use std::path::PathBuf;
use tmm::construct::Drafting;
use tmm::render;

#[derive(Parser)]
#[command(
    name = "tmm",
    version,
    about = "Graphical methods of the Theory of Mechanisms and Machines, drawn on scaled plates"
)]
pub(crate) struct Cli {
    #[command(subcommand)]
    pub(crate) command: Command,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum Format {
    Svg,
    Png,
    /// One PDF per scene, DIR/<scene>/<scene>.pdf: every sheet a page, 1:1.
    Pdf,
    /// The scene's explanatory note, DIR/<scene>/<scene>-note.pdf (as `tmm note`).
    Note,
    /// One self-contained page per scene, DIR/<scene>/<scene>.html: every sheet, the replay
    /// of every figure and the report, nothing fetched (`render` only).
    Html,
    /// One DXF drawing per sheet, DIR/<scene>/<plate>.dxf: 1:1 in mm, a layer per role,
    /// ГОСТ 2.303 line types (for KOMPAS-3D, AutoCAD; see docs/dxf.md).
    Dxf,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum ReportFormat {
    Md,
    Csv,
    Json,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum AuditFormat {
    Md,
    Json,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub(crate) enum LangArg {
    Ru,
    Uk,
    En,
}

/// Where and how `render` and `batch` draw.
#[derive(clap::Args)]
pub(crate) struct RenderArgs {
    /// Output folder.
    #[arg(long, default_value = "out")]
    pub(crate) out: PathBuf,
    /// Formats to write.
    #[arg(long, value_delimiter = ',', default_value = "svg,png")]
    pub(crate) format: Vec<Format>,
    /// Label language.
    #[arg(long, value_enum, default_value = "ru")]
    pub(crate) lang: LangArg,
    /// Resolution (mm) to which measured lengths are read before μ converts them; 0 = exact.
    /// `render` reads as a hand construction does (0.5 mm), `batch` exactly (the answer key).
    #[arg(long, allow_negative_numbers = true)]
    pub(crate) drafting: Option<f64>,
    /// PNG resolution, dots per inch: 1…2400, within 2^30 pixels per image (an A1 sheet up
    /// to 1177 dpi, A0 up to 832 dpi).
    #[arg(long, default_value_t = render::DEFAULT_DPI)]
    pub(crate) dpi: u32,
}

#[derive(Subcommand)]
pub(crate) enum Command {
    /// Render the plates of scenes to DIR/<scene>/<plate>.<ext> (PDF: DIR/<scene>/<scene>.pdf).
    Render {
        /// Scene files (constructions/*.toml).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        #[command(flatten)]
        how: RenderArgs,
    },
    /// Write the explanatory note of scenes: DIR/<scene>/<scene>-note.pdf (A4, ГОСТ 2.105
    /// text, ГОСТ 2.104 frames), every section the scene's studies allow.
    Note {
        /// Scene files (constructions/*.toml).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// The note's language.
        #[arg(long, value_enum, default_value = "ru")]
        lang: LangArg,
        /// Resolution (mm) to which measured lengths are read before μ converts them, as a
        /// hand construction does; 0 = exact.
        #[arg(long, default_value_t = Drafting::HAND.resolution_mm(), allow_negative_numbers = true)]
        drafting: f64,
    },
    /// Compare every value read off the plans and diagrams with its analytic twin.
    Report {
        /// Scene file.
        scene: PathBuf,
        /// Output format.
        #[arg(long, value_enum, default_value = "md")]
        format: ReportFormat,
        /// Resolution (mm) to which measured lengths are read; 0 = exact.
        #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
        drafting: f64,
        /// Language of the Markdown headings.
        #[arg(long, value_enum, default_value = "ru")]
        lang: LangArg,
    },
    /// Validate scenes and carry out their constructions without writing anything.
    Check {
        /// Scene files.
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
    },
    /// Speed against error: sweep each method's resolution, time it against its error, and
    /// write DIR/bench/bench.md, bench.json and bench.svg.
    Bench {
        /// Print the JSON instead of the Markdown table.
        #[arg(long)]
        json: bool,
        /// Output folder.
        #[arg(long, default_value = "out")]
        out: PathBuf,
        /// Small repetition counts (rough times, same errors).
        #[arg(long)]
        quick: bool,
        /// Only the studio's rows, `studio edit <scene>`: for every shipped scene the median
        /// time from an edit to its sheets as SVG and its report (what `tmm serve` answers).
        #[arg(long)]
        studio: bool,
        /// Folder holding shaper.toml and four-bar.toml.
        #[arg(long, default_value = "constructions")]
        scenes: PathBuf,
    },
    /// Every variant of a class: the template scene with each row of a variant grid (CSV:
    /// `variant,<scene key>,…`) set, rendered to DIR/<variant>/ on all cores, and the answer
    /// key of the template's `[answer_key]` values, DIR/answer-key.csv and .pdf.
    Batch {
        /// The template scene (constructions/*.toml).
        template: PathBuf,
        /// The variant grid (CSV).
        variants: PathBuf,
        #[command(flatten)]
        how: RenderArgs,
    },
    /// Check a student's table against the scene: each value (CSV: quantity, position,
    /// value, unit[, method]) right within the drafting error of a hand construction, a
    /// slip (scale, unit, sign, digits, another position or quantity, a known wrong formula)
    /// or wrong, with its exact value; the marked-up table on standard output, and with
    /// --pdf the sheet to return to the student.
    Audit {
        /// The scene the table belongs to (constructions/*.toml).
        scene: PathBuf,
        /// The student's table (CSV).
        table: PathBuf,
        /// Output format.
        #[arg(long, value_enum, default_value = "md")]
        format: AuditFormat,
        /// Write the marked-up table as a PDF sheet to this file.
        #[arg(long)]
        pdf: Option<PathBuf>,
        /// Language of the verdicts and the sheet.
        #[arg(long, value_enum, default_value = "ru")]
        lang: LangArg,
    },
    /// The studio: a local web page (127.0.0.1) to pick a shipped scene, edit it as a form
    /// or as text, and see its sheets and report re-drawn after each edit.
    Serve {
        /// Port to listen on (0: any free port; the address is printed).
        #[arg(long, default_value_t = 8040)]
        port: u16,
        /// Open the page in the system's browser.
        #[arg(long)]
        open: bool,
    },
    /// List the scenes in constructions/ with their plates.
    List {
        /// Folder to list.
        #[arg(long, default_value = "constructions")]
        dir: PathBuf,
    },
}
