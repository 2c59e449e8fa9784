//! The instructor's desk: every variant of a task, drawn from one template scene, and the
//! answer key over them (`tmm batch`).
//!
//! A variant grid is a CSV file. Its header is `variant` and then scene keys as dotted paths
//! into the template (`mechanism.crank.length`, `forces.link[1].mass`,
//! `mechanism.fixed[0].at[1]`; an index counts a `[[…]]` list's tables or an array's
//! elements from 0, in file order). Each row is one variant: its name (the folder its sheets
//! go to) and its values, in the units of the scene file; an empty cell takes the key out, so
//! that the scene's default holds (a scale the program chooses for each variant). A grid
//! whose header holds `;` and no `,` is read with `;` between the fields, and its numbers may
//! then carry a decimal comma.
//!
//! [`read_grid`] checks the whole grid against the template before anything is built: a key
//! the template does not have, a row with a field too few or too many, a value that is not
//! of the template's kind (a number, a whole number, a word), a name used twice — each is
//! refused with its line, column and key, and nothing is written. A variant whose scene is
//! then refused (a length out of range) or cannot be assembled or drawn (a crank that cannot
//! turn) is listed by [`run`] with its diagnosis, and the others are still written.

mod key;

use crate::render::{self, Options};
use crate::scene;
use crate::scene::user_table::{self, CellError};
use crate::study::{Session, Shared};
use key::row_of;
pub use key::{answer_columns, answer_key_csv, answer_key_pdf, write_answer_key, KeyColumn};
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use thiserror::Error;
use toml::{Table, Value};

/// Why a variant grid is refused as a whole.
#[derive(Debug, Error)]
pub enum GridError {
    /// The grid is not readable CSV, or its header is not `variant,<key>,…`.
    #[error("{}: {message}", .path.display())]
    Grid {
        /// The grid's file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
    /// One field of a row is refused.
    #[error(transparent)]
    Cell(#[from] CellError),
    /// The template is not a scene, or its answer key names a row its report lacks.
    #[error("{}: {message}", .path.display())]
    Template {
        /// The template's file.
        path: PathBuf,
        /// What is wrong.
        message: String,
    },
}

/// One variant of a grid: its name and its row. Its scene's text is made when it is drawn
/// ([`Variant::text`]), so that a class of thousands holds its rows, not thousands of scenes.
#[derive(Debug, Clone)]
pub struct Variant {
    /// The variant's name: its output folder.
    pub name: String,
    /// The grid's line it came from.
    pub line: u64,
    /// The row's values, one per key of the grid's header (checked against the template).
    cells: Vec<String>,
    /// The template and the grid's keys, shared by every variant of the grid.
    grid: Arc<Template>,
}

/// What every variant of a grid shares: the template's table and the keys the grid sets.
#[derive(Debug)]
struct Template {
    base: Table,
    paths: Vec<Vec<Step>>,
    decimal_comma: bool,
}

impl Template {
    /// The template with `cells` set (an empty cell takes its key out); the column (from 0,
    /// among the keys) and the message of the first cell refused.
    fn with(&self, cells: &[String]) -> Result<Table, (usize, String)> {
        let mut table = self.base.clone();
        for (c, (path, text)) in self.paths.iter().zip(cells).enumerate() {
            if text.trim().is_empty() {
                remove(&mut table, path).map_err(|m| (c, m))?;
                continue;
            }
            let at = slot(&mut table, path).map_err(|m| (c, m))?;
            assign(at, text, self.decimal_comma).map_err(|m| (c, m))?;
        }
        Ok(table)
    }
}

impl Variant {
    /// The variant's scene: the template's text with the row's values set.
    ///
    /// # Errors
    /// The message when the scene cannot be written out as TOML (the row itself was checked
    /// by [`read_grid`]).
    pub fn text(&self) -> Result<String, String> {
        let table = self.grid.with(&self.cells).map_err(|(_, m)| m)?;
        toml::to_string(&table).map_err(|e| e.to_string())
    }
}

/// One step of a key path: a table's key or an array's index.
#[derive(Debug, Clone, PartialEq)]
enum Step {
    Key(String),
    Index(usize),
}

/// `a.b[0].c[1]` as steps; `None` when it is not such a path.
fn steps(key: &str) -> Option<Vec<Step>> {
    let mut out = Vec::new();
    for part in key.split('.') {
        let (name, mut rest) = part.split_at(part.find('[').unwrap_or(part.len()));
        if name.is_empty() || !name.chars().all(|c| c.is_alphanumeric() || c == '_') {
            return None;
        }
        out.push(Step::Key(name.into()));
        while let Some(r) = rest.strip_prefix('[') {
            let (index, after) = r.split_once(']')?;
            out.push(Step::Index(index.parse().ok()?));
            rest = after;
        }
        if !rest.is_empty() {
            return None;
        }
    }
    Some(out)
}

/// The value at `path` in `table`, or why there is none.
fn slot<'t>(table: &'t mut Table, path: &[Step]) -> Result<&'t mut Value, String> {
    let Some((Step::Key(first), rest)) = path.split_first() else {
        return Err("expected a key".into());
    };
    let mut at = table
        .get_mut(first)
        .ok_or_else(|| format!("the template has no `{first}`"))?;
    for step in rest {
        at = match (step, at) {
            (Step::Key(k), Value::Table(t)) => t
                .get_mut(k)
                .ok_or_else(|| format!("the template has no `{k}` there"))?,
            (Step::Index(i), Value::Array(a)) => {
                let n = a.len();
                a.get_mut(*i).ok_or_else(|| {
                    format!("index {i} out of range: the template has {n} (from 0)")
                })?
            }
            (Step::Key(k), _) => return Err(format!("`{k}`: the template has no table there")),
            (Step::Index(i), _) => return Err(format!("[{i}]: the template has no list there")),
        };
    }
    Ok(at)
}

/// Take the value at `path` out of `table` (an empty cell: the scene's default, e.g. a scale
/// the program chooses for each variant).
fn remove(table: &mut Table, path: &[Step]) -> Result<(), String> {
    let Some((Step::Key(last), parent)) = path.split_last() else {
        return Err("an element of a list cannot be left empty".into());
    };
    let parent = if parent.is_empty() {
        table
    } else {
        slot(table, parent)?
            .as_table_mut()
            .ok_or_else(|| format!("`{last}`: the template has no table there"))?
    };
    parent.remove(last);
    Ok(())
}

/// Set `slot` to `text`, read as the kind of value the template has there.
fn assign(slot: &mut Value, text: &str, decimal_comma: bool) -> Result<(), String> {
    let t = text.trim();
    let number = || -> Result<f64, String> {
        let s = if decimal_comma {
            t.replace(',', ".")
        } else {
            t.to_string()
        };
        match s.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(format!("{t:?}: expected a number")),
        }
    };
    *slot = match slot {
        Value::Float(_) => Value::Float(number()?),
        Value::Integer(_) => {
            let x = number()?;
            if x.fract() != 0.0 || x.abs() > 9.0e15 {
                return Err(format!("{t:?}: expected a whole number"));
            }
            Value::Integer(x as i64)
        }
        Value::Boolean(_) => match t {
            "true" => Value::Boolean(true),
            "false" => Value::Boolean(false),
            _ => return Err(format!("{t:?}: expected true or false")),
        },
        Value::String(_) => Value::String(t.to_string()),
        _ => {
            return Err(
                "a table or a list in the template: name one of its values (e.g. key[0])".into(),
            )
        }
    };
    Ok(())
}

/// Whether `name` may name a folder: letters, digits, `-`, `_`, `.`, not starting with `.`,
/// and not the answer key's files.
fn folder_name(name: &str) -> bool {
    !name.is_empty()
        && !name.starts_with('.')
        && !name.starts_with("answer-key.")
        && name
            .chars()
            .all(|c| c.is_alphanumeric() || matches!(c, '-' | '_' | '.'))
}

/// The variants of the grid `grid` (the text of the file at `grid_path`) over the template
/// scene's text `template`, every value checked (see the module's documentation).
///
/// # Errors
/// [`GridError`] for the first problem, with its line, column and key.
pub fn read_grid(template: &str, grid: &str, grid_path: &Path) -> Result<Vec<Variant>, GridError> {
    let whole = |message: String| GridError::Grid {
        path: grid_path.to_path_buf(),
        message,
    };
    let base: Table = toml::from_str(template)
        .map_err(|e| whole(format!("the template is not TOML: {}", e.message())))?;
    let (mut reader, semicolons) = user_table::reader(grid);
    let header: Vec<String> = reader
        .headers()
        .map_err(|e| whole(format!("the header: {e}")))?
        .iter()
        .map(|h| h.trim().to_string())
        .collect();
    if header.first().map(String::as_str) != Some("variant") {
        return Err(whole(
            "the header must start with `variant`, then the scene keys the variants set".into(),
        ));
    }
    let mut paths = Vec::new();
    for (c, key) in header.iter().enumerate().skip(1) {
        let cell = |message: String| {
            GridError::Cell(CellError {
                path: grid_path.to_path_buf(),
                line: 1,
                column: c + 1,
                key: key.clone(),
                message,
            })
        };
        if header[1..c].contains(key) {
            return Err(cell("the key appears twice".into()));
        }
        let path = steps(key).ok_or_else(|| {
            cell("expected a key path such as mechanism.crank.length or forces.link[1].mass".into())
        })?;
        // The key must name one value of the template.
        let mut probe = base.clone();
        let at = slot(&mut probe, &path).map_err(cell)?;
        if matches!(at, Value::Table(_) | Value::Array(_)) {
            return Err(cell(
                "a table or a list in the template: name one of its values (e.g. key[0])".into(),
            ));
        }
        paths.push(path);
    }
    let grid = Arc::new(Template {
        base,
        paths,
        decimal_comma: semicolons,
    });
    let mut variants: Vec<Variant> = Vec::new();
    let mut names = HashSet::new();
    for record in reader.records() {
        let record = record.map_err(|e| whole(e.to_string()))?;
        let line = record.position().map_or(0, |p| p.line());
        let cell = |column: usize, message: String| {
            GridError::Cell(CellError {
                path: grid_path.to_path_buf(),
                line,
                column: column + 1,
                key: header.get(column).cloned().unwrap_or_default(),
                message,
            })
        };
        if record.iter().all(|f| f.trim().is_empty()) {
            continue;
        }
        if record.len() != header.len() {
            let column = record.len().min(header.len());
            return Err(cell(
                column,
                format!("{} fields, the header has {}", record.len(), header.len()),
            ));
        }
        let name = record[0].trim().to_string();
        if !folder_name(&name) {
            return Err(cell(
                0,
                format!("{name:?}: a variant's name is its folder: letters, digits, -, _ or ."),
            ));
        }
        if !names.insert(name.clone()) {
            return Err(cell(0, format!("{name:?}: a second variant of that name")));
        }
        let cells: Vec<String> = record.iter().skip(1).map(str::to_string).collect();
        // Checked now, made again when drawn: nothing of a grid is drawn before all of it
        // is accepted.
        let table = grid.with(&cells).map_err(|(c, m)| cell(c + 1, m))?;
        toml::to_string(&table).map_err(|e| whole(e.to_string()))?;
        variants.push(Variant {
            name,
            line,
            cells,
            grid: Arc::clone(&grid),
        });
    }
    if variants.is_empty() {
        return Err(whole("no variant: expected a row after the header".into()));
    }
    Ok(variants)
}

/// The progress bar of a batch of `n` variants, drawn to `target` (standard error on a
/// terminal, hidden otherwise): the variants done and the last one's name.
pub fn progress_bar(n: usize, target: indicatif::ProgressDrawTarget) -> indicatif::ProgressBar {
    indicatif::ProgressBar::with_draw_target(Some(n as u64), target).with_style(
        indicatif::ProgressStyle::with_template("{bar:40} {pos}/{len} {msg}")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    )
}

/// What became of one variant.
#[derive(Debug)]
pub struct VariantOutcome {
    /// The variant's name.
    pub name: String,
    /// The files written and the answer key's exact values (`None`: the report lacks the
    /// row), or why the variant was not drawn (the grid's line, the key, position or group).
    pub result: Result<(Vec<PathBuf>, Vec<Option<f64>>), String>,
}

/// One variant: its scene (named `<name>.toml` beside the template), its files rendered and
/// written into `out/<name>/` with its task sheet (`task.pdf`, a task with a mechanism), and
/// the exact values of `columns` from its report; its session shares `shared` with the
/// other variants'.
fn one(
    v: &Variant,
    template: &Path,
    shared: &Arc<Shared>,
    out: &Path,
    options: &Options,
    columns: &[KeyColumn],
) -> Result<(Vec<PathBuf>, Vec<Option<f64>>), String> {
    // The scene is named after the variant (its folder, its default title); its messages
    // name the grid's line instead of a file that does not exist.
    let path = template.with_file_name(format!("{}.toml", v.name));
    let why = |e: &dyn std::fmt::Display| {
        let text = e.to_string();
        let prefix = format!("{}: ", path.display());
        format!(
            "line {}: {}",
            v.line,
            text.strip_prefix(&prefix).unwrap_or(&text)
        )
    };
    let text = v.text().map_err(|e| why(&e))?;
    let scene = scene::parse(&text, &path).map_err(|e| why(&e))?;
    let session = Session::sharing(&scene, options.drafting, Arc::clone(shared));
    // The task sheet to hand out, for a task with a mechanism: made before anything of the
    // variant is written, so that a variant whose task sheet fails leaves no folder.
    let task = match scene.mechanism {
        Some(_) => Some(
            crate::sheets::task_sheet(&session, &v.name, options.lang)
                .map_err(|e| why(&e))
                .and_then(|plates| crate::plate::plates_to_pdf(&plates).map_err(|e| why(&e)))?,
        ),
        None => None,
    };
    let mut files = render::session_files(&session, out, options).map_err(|e| why(&e))?;
    if let Some(pdf) = task {
        files.push((out.join(&v.name).join("task.pdf"), pdf));
    }
    // The report's values before anything is written, and the variant's sheets with its
    // task sheet written together: a variant is whole or absent.
    let values = if columns.is_empty() {
        Vec::new()
    } else {
        let report = session.report().map_err(|e| why(&e))?;
        columns
            .iter()
            .map(|c| row_of(&report.rows, &c.item).map(|r| r.analytic))
            .collect()
    };
    crate::plate::write_all_atomic(&files).map_err(|(path, e)| {
        format!(
            "line {}: {}: cannot write: {e} (nothing of the variant written)",
            v.line,
            path.display()
        )
    })?;
    Ok((files.into_iter().map(|(path, _)| path).collect(), values))
}

/// A memoized result not used by the last this many variants is dropped.
const MEMO_AGE: usize = 8;

/// Render every variant into `out/<name>/`, each written atomically on its own; a variant
/// that fails is reported in its outcome and the others go on. `done` is called with each
/// variant's name as it finishes (a progress bar). Outcomes in grid order.
///
/// The variants are drawn side by side on as many plain threads as rayon's pool has
/// ([`crate::threads::each`]), not on the pool: a pool thread waiting inside one variant's
/// PDF would take up the next variant on its stack, and a class of hundreds overflows it.
/// At most that many variants are in memory at once, whatever the grid's length.
pub fn run(
    variants: &[Variant],
    template: &Path,
    out: &Path,
    options: &Options,
    columns: &[KeyColumn],
    done: &(dyn Fn(&str) + Sync),
) -> Vec<VariantOutcome> {
    let mut results: Vec<Option<VariantOutcome>> = variants.iter().map(|_| None).collect();
    // What the variants' sessions share (the gear pair's blocking contour, traced once for
    // the variants of one pair).
    let shared = Arc::new(Shared::default());
    crate::threads::each(
        variants,
        rayon::current_num_threads(),
        |v| one(v, template, &shared, out, options, columns),
        |k, result| {
            // What the PDF writer and the typesetter memoized for variants long done goes:
            // its caches would otherwise grow with every variant of the class.
            comemo::evict(MEMO_AGE);
            let name = variants[k].name.clone();
            done(&name);
            results[k] = Some(VariantOutcome { name, result });
        },
    );
    results.into_iter().flatten().collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn key_paths_step_through_tables_and_lists() {
        assert_eq!(
            steps("forces.link[1].mass"),
            Some(vec![
                Step::Key("forces".into()),
                Step::Key("link".into()),
                Step::Index(1),
                Step::Key("mass".into())
            ])
        );
        assert_eq!(steps("mechanism.fixed[0].at[1]").map(|s| s.len()), Some(5));
        for bad in ["", "a..b", "a[", "a[x]", "a[1]b", "a b", "[0]"] {
            assert_eq!(steps(bad), None, "{bad}");
        }
    }

    const TEMPLATE: &str = "[a]\nx = 1.5\nn = 3\nname = \"p\"\nat = [0.0, 2.0]\n[[a.l]]\nm = 2.0\n";

    fn grid(csv: &str) -> Result<Vec<Variant>, GridError> {
        read_grid(TEMPLATE, csv, Path::new("g.csv"))
    }

    #[test]
    fn a_row_sets_its_values_as_the_template_has_them() {
        let v = grid("variant,a.x,a.n,a.at[1],a.l[0].m,a.name\n01,2.5,4,7,9.5,q\n").unwrap();
        let t: Table = toml::from_str(&v[0].text().unwrap()).unwrap();
        assert_eq!(t["a"]["x"].as_float(), Some(2.5));
        assert_eq!(t["a"]["n"].as_integer(), Some(4));
        assert_eq!(t["a"]["at"][1].as_float(), Some(7.0));
        assert_eq!(t["a"]["l"][0]["m"].as_float(), Some(9.5));
        assert_eq!(t["a"]["name"].as_str(), Some("q"));
        // Semicolons and decimal commas.
        let v = grid("variant;a.x\nv1;2,25\n").unwrap();
        let t: Table = toml::from_str(&v[0].text().unwrap()).unwrap();
        assert_eq!(t["a"]["x"].as_float(), Some(2.25));
        // An empty cell takes the key out; a list's element cannot be.
        let v = grid("variant,a.x,a.l[0].m\nv1,,\n").unwrap();
        let t: Table = toml::from_str(&v[0].text().unwrap()).unwrap();
        assert!(t["a"].get("x").is_none() && t["a"]["l"][0].get("m").is_none());
        assert!(t["a"].get("n").is_some());
        assert!(refused("variant,a.at[0]\nv1,\n").contains("cannot be left empty"));
    }

    /// The message of a refused grid, with its line, column and key.
    fn refused(csv: &str) -> String {
        grid(csv).expect_err(csv).to_string()
    }

    #[test]
    fn a_bad_grid_is_refused_with_its_line_column_and_key() {
        let m = refused("variant,a.x,a.n\n1,2.0,3\n2,abc,3\n");
        assert!(
            m.contains("line 3, column 2 (a.x)") && m.contains("number"),
            "{m}"
        );
        let m = refused("variant,a.x,a.n\n1,2.0\n");
        assert!(
            m.contains("line 2, column 3 (a.n)") && m.contains("2 fields"),
            "{m}"
        );
        let m = refused("variant,a.y\n1,2.0\n");
        assert!(
            m.contains("line 1, column 2 (a.y)") && m.contains("no `y`"),
            "{m}"
        );
        let m = refused("variant,a.n\n1,2.5\n");
        assert!(m.contains("whole number"), "{m}");
        let m = refused("variant,a.l[3].m\n1,2.5\n");
        assert!(m.contains("out of range"), "{m}");
        let m = refused("variant,a.at\n1,2.5\n");
        assert!(m.contains("name one of its values"), "{m}");
        let m = refused("variant,a.x\n1,2\n1,3\n");
        assert!(
            m.contains("line 3, column 1") && m.contains("second variant"),
            "{m}"
        );
        let m = refused("variant,a.x\n../up,2\n");
        assert!(m.contains("folder"), "{m}");
        let m = refused("variant,a.x\nanswer-key.csv,2\n");
        assert!(m.contains("folder"), "{m}");
        let m = refused("name,a.x\n1,2\n");
        assert!(m.contains("must start with `variant`"), "{m}");
        let m = refused("variant,a.x\n");
        assert!(m.contains("no variant"), "{m}");
    }
}
