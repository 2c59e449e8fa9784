//! The `tmm` command line: parse arguments, call the library, print errors.
//!
//! Exit status: 0 success, 2 bad input or usage, 1 a construction that cannot be carried out.

mod allocator;

mod cli;

use clap::Parser;
use cli::{AuditFormat, Cli, Command, Format, LangArg, RenderArgs, ReportFormat};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use tmm::construct::Drafting;
use tmm::render::{self, RenderError};
use tmm::scale::Lang;
use tmm::scene::{self, Scene};
use tmm::study::Session;

/// A failure with its exit status; an empty message has been reported already.
struct Failure {
    code: u8,
    message: String,
}

impl Failure {
    fn input(message: impl Into<String>) -> Self {
        Self {
            code: 2,
            message: message.into(),
        }
    }
    fn construction(message: impl Into<String>) -> Self {
        Self {
            code: 1,
            message: message.into(),
        }
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Render { scenes, how } => render(&scenes, &how),
        Command::Check { scenes } => check(&scenes),
        Command::Note {
            scenes,
            out,
            lang,
            drafting,
        } => note(&scenes, &out, lang, drafting),
        Command::Report {
            scene,
            format,
            drafting,
            lang,
        } => report(&scene, format, drafting, lang),
        Command::Batch {
            template,
            variants,
            how,
        } => batch(&template, &variants, &how),
        Command::Audit {
            scene,
            table,
            format,
            pdf,
            lang,
        } => audit(&scene, &table, format, pdf.as_deref(), lang),
        Command::List { dir } => list(&dir),
        Command::Serve { port, open } => tmm::studio::serve(port, |addr| {
            emit(&format!("tmm studio: http://{addr}/ (Ctrl-C stops it)"));
            if open {
                tmm::studio::open_browser(&format!("http://{addr}/"));
            }
        })
        .map_err(|e| Failure::input(e.to_string())),
        Command::Bench {
            json,
            out,
            quick,
            studio,
            scenes,
        } => bench(json, &out, quick, studio, scenes),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(f) => {
            if !f.message.is_empty() {
                eprintln!("error: {}", f.message);
            }
            ExitCode::from(f.code)
        }
    }
}

/// Print a line to standard output; a closed pipe (`tmm report … | head`) is not an error.
fn emit(line: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stdout().lock(), "{line}");
}

fn load_all(paths: &[PathBuf]) -> Result<Vec<Scene>, Failure> {
    paths.iter().map(PathBuf::as_path).map(load).collect()
}

/// A scene read, its warnings on standard error (`warning: path: key: …`).
fn load(path: &Path) -> Result<Scene, Failure> {
    let s = scene::load(path).map_err(|e| Failure::input(e.to_string()))?;
    for w in &s.warnings {
        eprintln!("warning: {}: {w}", path.display());
    }
    Ok(s)
}

fn options(lang: LangArg, drafting: f64) -> Result<(Lang, Drafting), Failure> {
    let drafting = Drafting::new(drafting).ok_or_else(|| {
        Failure::input(format!(
            "--drafting {drafting}: expected a resolution ≥ 0 mm"
        ))
    })?;
    Ok((language(lang), drafting))
}

/// A file that cannot be written: the output the user named is at fault (status 2, as
/// `render`'s).
fn cannot_write(path: &Path, e: &std::io::Error) -> Failure {
    Failure::input(format!("{}: cannot write: {e}", path.display()))
}

fn language(lang: LangArg) -> Lang {
    match lang {
        LangArg::Ru => Lang::Ru,
        LangArg::Uk => Lang::Uk,
        LangArg::En => Lang::En,
    }
}

/// A failure to render: bad input (status 2) or a construction (status 1), with the
/// library's message.
fn render_failure(e: RenderError) -> Failure {
    if e.is_input() {
        Failure::input(e.to_string())
    } else {
        Failure::construction(e.to_string())
    }
}

/// What `--format`, `--lang`, `--drafting` (`fallback` when not given) and `--dpi` ask of a
/// rendering.
fn render_options(how: &RenderArgs, fallback: Drafting) -> Result<render::Options, Failure> {
    let resolution = how.drafting.unwrap_or(fallback.resolution_mm());
    let (lang, drafting) = options(how.lang, resolution)?;
    let (formats, dpi) = (&how.format, how.dpi);
    if !(1..=2400).contains(&dpi) {
        return Err(Failure::input(format!("--dpi {dpi}: expected 1…2400")));
    }
    Ok(render::Options {
        lang,
        drafting,
        formats: render::Formats {
            svg: formats.contains(&Format::Svg),
            png: formats.contains(&Format::Png),
            pdf: formats.contains(&Format::Pdf),
            note: formats.contains(&Format::Note),
            dxf: formats.contains(&Format::Dxf),
        },
        dpi,
    })
}

fn render(paths: &[PathBuf], how: &RenderArgs) -> Result<(), Failure> {
    let options = render_options(how, Drafting::HAND)?;
    let out = how.out.as_path();
    let scenes = load_all(paths)?;
    if let Some(s) = scenes.iter().find(|s| s.plates.is_empty()) {
        return Err(nothing_to_draw(s));
    }
    distinct_stems(&scenes, out)?;
    let mut files = render::files(&scenes, out, &options).map_err(render_failure)?;
    if how.format.contains(&Format::Html) {
        let (lang, drafting) = (options.lang, options.drafting);
        let pages = tmm::studio::html::files(&scenes, out, lang, drafting);
        files.extend(pages.map_err(render_failure)?);
    }
    let written = render::write(files).map_err(render_failure)?;
    for path in &written {
        emit(&path.display().to_string());
    }
    Ok(())
}

/// The text of a file (a scene or a grid), at most a scene's size.
fn read_text(path: &Path) -> Result<String, Failure> {
    scene::read(path).map_err(|e| Failure::input(e.to_string()))
}

/// `tmm batch`: the grid checked whole against the template (nothing written when it is
/// refused), every variant rendered on all cores with a progress bar on a terminal, the
/// answer key written; each variant that fails is named with its diagnosis, and the status
/// is 1 when any did.
fn batch(template: &Path, grid: &Path, how: &RenderArgs) -> Result<(), Failure> {
    use std::io::IsTerminal as _;
    if how.format.contains(&Format::Html) {
        return Err(Failure::input(
            "--format html: a class's variants are drawn as sheets; write a variant's page with tmm render",
        ));
    }
    let options = render_options(how, Drafting::EXACT)?;
    let out = how.out.as_path();
    let scene = load(template)?;
    if scene.plates.is_empty() {
        return Err(nothing_to_draw(&scene));
    }
    let variants = tmm::batch::read_grid(&read_text(template)?, &read_text(grid)?, grid)
        .map_err(|e| Failure::input(e.to_string()))?;
    let columns = tmm::batch::answer_columns(&scene, options.drafting)
        .map_err(|e| Failure::input(e.to_string()))?;
    let bar = tmm::batch::progress_bar(
        variants.len(),
        if std::io::stderr().is_terminal() {
            indicatif::ProgressDrawTarget::stderr()
        } else {
            indicatif::ProgressDrawTarget::hidden()
        },
    );
    let outcomes = tmm::batch::run(&variants, template, out, &options, &columns, &|name| {
        bar.set_message(name.to_string());
        bar.inc(1);
    });
    bar.finish_and_clear();
    // Every variant's diagnosis is printed before the answer key is written: a key that
    // cannot be written loses none of them.
    let failed = print_outcomes(&outcomes);
    let code = match tmm::batch::write_answer_key(&scene, out, &columns, &outcomes, options.lang) {
        Ok(written) => {
            written.iter().for_each(|p| emit(&p.display().to_string()));
            u8::from(failed > 0)
        }
        Err((None, e)) => {
            eprintln!("error: the answer key's sheet: {e}");
            1
        }
        Err((Some(path), e)) => {
            eprintln!(
                "error: {}: cannot write the answer key: {e} (the variants listed above are written)",
                path.display()
            );
            2
        }
    };
    let message = match failed {
        0 => String::new(),
        _ => format!(
            "{failed} of {} variants not drawn (listed above; the others are written)",
            outcomes.len()
        ),
    };
    match code {
        0 => Ok(()),
        _ => Err(Failure { code, message }),
    }
}

/// Each variant of a batch on a line (files on stdout, its diagnosis on stderr); the failed.
fn print_outcomes(outcomes: &[tmm::batch::VariantOutcome]) -> usize {
    let mut failed = 0;
    for o in outcomes {
        match &o.result {
            Ok((files, _)) => emit(&format!(
                "{}: {} file{}",
                o.name,
                files.len(),
                if files.len() == 1 { "" } else { "s" }
            )),
            Err(why) => {
                failed += 1;
                eprintln!("error: variant {}: {why}", o.name);
            }
        }
    }
    failed
}

/// `tmm audit`: the table read whole against the scene's report (refused with its line,
/// column and key, nothing written), each value classified, the marked-up table printed and
/// the sheet written when asked for.
fn audit(
    path: &Path,
    table: &Path,
    format: AuditFormat,
    pdf: Option<&Path>,
    lang: LangArg,
) -> Result<(), Failure> {
    let lang = language(lang);
    let s = load(path)?;
    if !s.has_study() {
        return Err(nothing_to_construct(&s));
    }
    let auditor = tmm::audit::Auditor::new(&s).map_err(|e| Failure::construction(e.to_string()))?;
    let entries = tmm::audit::read_table(&read_text(table)?, table, &auditor)
        .map_err(|e| Failure::input(e.to_string()))?;
    let audited = auditor.audit(&entries);
    if let Some(pdf) = pdf {
        let plates = tmm::audit::to_sheet(&s, &audited, lang)
            .map_err(|e| Failure::construction(format!("the audit's sheet: {e}")))?;
        let bytes = tmm::plate::plates_to_pdf(&plates)
            .map_err(|e| Failure::construction(format!("the audit's sheet: {e}")))?;
        tmm::plate::write_atomic(pdf, &bytes).map_err(|e| cannot_write(pdf, &e))?;
    }
    emit(&match format {
        AuditFormat::Md => tmm::audit::to_markdown(&s.stem, &audited, lang),
        AuditFormat::Json => tmm::audit::to_json(&audited),
    });
    Ok(())
}

fn note(paths: &[PathBuf], out: &Path, lang: LangArg, drafting: f64) -> Result<(), Failure> {
    let (lang, drafting) = options(lang, drafting)?;
    let scenes = load_all(paths)?;
    if let Some(s) = scenes.iter().find(|s| !s.has_study()) {
        return Err(nothing_to_construct(s));
    }
    distinct_stems(&scenes, out)?;
    let written = render::notes(&scenes, out, lang, drafting).map_err(render_failure)?;
    for path in &written {
        emit(&path.display().to_string());
    }
    Ok(())
}

/// Two scenes of one run must not write the same folder.
fn distinct_stems(scenes: &[Scene], out: &Path) -> Result<(), Failure> {
    for (k, a) in scenes.iter().enumerate() {
        if let Some(b) = scenes[..k].iter().find(|b| b.stem == a.stem) {
            return Err(Failure::input(format!(
                "{} and {}: both would write {}; render them in separate runs with different --out",
                b.path.display(),
                a.path.display(),
                out.join(&a.stem).display()
            )));
        }
    }
    Ok(())
}

fn report(path: &Path, format: ReportFormat, drafting: f64, lang: LangArg) -> Result<(), Failure> {
    let (lang, drafting) = options(lang, drafting)?;
    let s = load(path)?;
    if !s.has_study() {
        return Err(nothing_to_construct(&s));
    }
    let rep = Session::new(&s, drafting)
        .report()
        .map_err(|e| Failure::construction(format!("{}: {e}", s.path.display())))?;
    let text = match format {
        ReportFormat::Md => rep.to_markdown(lang),
        ReportFormat::Csv => rep.to_csv(),
        ReportFormat::Json => rep.to_json(),
    };
    emit(&text);
    Ok(())
}

/// A scene without a study to carry out.
fn nothing_to_construct(s: &Scene) -> Failure {
    Failure::input(format!(
        "{}: the scene asks for nothing to construct (no [mechanism], no [balancing] and no plates)",
        s.path.display()
    ))
}

/// A scene without a plate to draw: without a study, or with `[plates] wanted = []`.
fn nothing_to_draw(s: &Scene) -> Failure {
    if s.has_study() {
        Failure::input(format!(
            "{}: plates.wanted = []: the scene asks for no plate to draw: expected at least one plate",
            s.path.display()
        ))
    } else {
        nothing_to_construct(s)
    }
}

/// Check every scene: a line for each (`path: ok` on standard output, `error: …` on standard
/// error); the worst status (2 bad input > 1 construction > 0).
fn check(paths: &[PathBuf]) -> Result<(), Failure> {
    let mut worst: Option<Failure> = None;
    for path in paths {
        let result = load(path).and_then(|s| {
            if s.plates.is_empty() {
                return Err(nothing_to_draw(&s));
            }
            render::check(&s).map_err(render_failure)
        });
        match result {
            Ok(()) => emit(&format!("{}: ok", path.display())),
            Err(f) => {
                eprintln!("error: {}", f.message);
                if worst.as_ref().is_none_or(|w| f.code > w.code) {
                    worst = Some(f);
                }
            }
        }
    }
    // Every failure has been printed on its own line.
    worst.map_or(Ok(()), |w| {
        Err(Failure {
            code: w.code,
            message: String::new(),
        })
    })
}

fn bench(
    json: bool,
    out: &Path,
    quick: bool,
    studio: bool,
    scenes: PathBuf,
) -> Result<(), Failure> {
    let opts = tmm::bench::BenchOptions {
        scenes,
        quick,
        studio,
    };
    let b = tmm::bench::run(&opts).map_err(|e| Failure::construction(e.to_string()))?;
    let (md, js) = (b.to_markdown(), b.to_json());
    let dir = out.join("bench");
    for (name, text) in [
        ("bench.md", &md),
        ("bench.json", &js),
        ("bench.svg", &b.to_svg_plot()),
    ] {
        let path = dir.join(name);
        tmm::plate::write_atomic(&path, text.as_bytes()).map_err(|e| cannot_write(&path, &e))?;
    }
    println!("{}", if json { js } else { md });
    Ok(())
}

fn list(dir: &Path) -> Result<(), Failure> {
    let entries =
        scene::files_in(dir).map_err(|e| Failure::input(format!("{}: {e}", dir.display())))?;
    for p in entries {
        match scene::load(&p) {
            Ok(s) => {
                let plates: Vec<&str> = s.plates.iter().map(|k| k.stem()).collect();
                emit(&format!(
                    "{}\t{}\t{}",
                    p.display(),
                    s.title.title,
                    plates.join(", ")
                ));
            }
            Err(e) => emit(&format!(
                "{}\tinvalid: {}",
                p.display(),
                e.to_string().lines().next().unwrap_or("")
            )),
        }
    }
    Ok(())
}
