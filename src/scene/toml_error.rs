//! A TOML reader's error said in the scene's terms: its line and column, the key path it
//! falls in, the offending text, an unknown or twice-written table named as a table.

use super::check::item;
use super::error::SceneError;
use std::path::Path;

/// A TOML reader error with its line, column, the key path it falls in and the offending text.
pub(super) fn toml_error(text: &str, path: &Path, e: &toml::de::Error) -> SceneError {
    let span = e.span().unwrap_or(0..0);
    let (line, column) = line_column(text, span.start);
    let value = text
        .get(span.clone())
        .map(str::trim)
        .filter(|s| !s.is_empty() && !s.contains('\n') && s.chars().count() <= 60);
    if let Some(e) = unknown_table(text, path, span.clone(), e) {
        return e;
    }
    if let Some(e) = duplicate_table(text, path, span.clone(), e) {
        return e;
    }
    let mut key = key_path_at(text, span.start);
    let is_key = text
        .get(span.end..)
        .is_some_and(|rest| rest.trim_start().starts_with('='));
    let value = match value {
        // An unknown key: the offending text is the key itself.
        Some(k) if is_key => {
            key = Some(key.map_or_else(|| k.to_string(), |base| format!("{base}.{k}")));
            None
        }
        v => v.map(str::to_string),
    };
    SceneError::Toml {
        path: path.to_path_buf(),
        line,
        column,
        key,
        value,
        message: compact_numbers(e.message().trim()),
    }
}

/// The reader's message with every number quoted in backticks written compactly (`1e300`,
/// not 301 digits; `nan`, not `NaN`), the way the scene writes it.
fn compact_numbers(message: &str) -> String {
    let mut out = String::new();
    for (k, part) in message.split('`').enumerate() {
        if k > 0 {
            out.push('`');
        }
        match part.parse::<f64>() {
            Ok(v) if k % 2 == 1 && (part.len() > 24 || v.is_nan()) => {
                out.push_str(&super::check::number(v));
            }
            _ => out.push_str(part),
        }
    }
    out
}

/// An unknown table: the reader's "unknown field `foo`" at a table header `[foo]` (or
/// `[[foo]]`, `[cam.foo]`) said as "unknown table `[foo]`".
fn unknown_table(
    text: &str,
    path: &Path,
    span: std::ops::Range<usize>,
    e: &toml::de::Error,
) -> Option<SceneError> {
    let message = e.message().trim();
    let rest = message.strip_prefix("unknown field `")?;
    let (field, tail) = rest.split_once('`')?;
    let line_start = text.get(..span.start)?.rfind('\n').map_or(0, |k| k + 1);
    let line = text.get(line_start..)?.lines().next()?;
    let header = line.trim_start();
    if !header.starts_with('[') {
        return None;
    }
    // The header's name up to the unknown part: `[cam.foo.x]` names `cam.foo`.
    let upto = text.get(line_start..span.end)?.trim_start();
    let name = upto.trim_start_matches('[').trim();
    let double = header.starts_with("[[");
    let shown = if double {
        format!("[[{name}]]")
    } else {
        format!("[{name}]")
    };
    if !name.ends_with(field) {
        return None;
    }
    Some(table_error(
        (text, path),
        span.start,
        name,
        format!("unknown table `{shown}`{tail}"),
    ))
}

/// A refusal of the table `name` whose header is at byte `offset` of the scene.
fn table_error(
    (text, path): (&str, &Path),
    offset: usize,
    name: &str,
    message: String,
) -> SceneError {
    let (line, column) = line_column(text, offset);
    SceneError::Toml {
        path: path.to_path_buf(),
        line,
        column,
        key: Some(name.to_string()),
        value: None,
        message,
    }
}

/// A table written twice: the reader's "duplicate key" at a table header `[a.b]` said as
/// "the table `[a.b]` is written twice", with the line of its first header.
fn duplicate_table(
    text: &str,
    path: &Path,
    span: std::ops::Range<usize>,
    e: &toml::de::Error,
) -> Option<SceneError> {
    if !e.message().trim().starts_with("duplicate key") {
        return None;
    }
    let line_start = text.get(..span.start)?.rfind('\n').map_or(0, |k| k + 1);
    let header = text.get(line_start..)?.lines().next()?.trim();
    let header = header.split('#').next().unwrap_or(header).trim();
    if !header.starts_with('[') || header.starts_with("[[") {
        return None;
    }
    let name = header.trim_start_matches('[').trim_end_matches(']').trim();
    let first = text
        .get(..line_start)?
        .lines()
        .position(|l| l.split('#').next().unwrap_or(l).trim() == header)
        .map_or_else(String::new, |k| format!(" (first at line {})", k + 1));
    Some(table_error(
        (text, path),
        line_start,
        name,
        format!("the table `[{name}]` is written twice{first}: each table once"),
    ))
}

/// 1-based line and column (in characters) of byte `offset`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// The key path (`mechanism.group[1].guide.dir`) of the text at byte `offset`, read from the
/// table headers above it and the keys on its line; `None` when nothing can be told.
fn key_path_at(text: &str, offset: usize) -> Option<String> {
    let before = text.get(..offset)?;
    let mut table = String::new();
    let mut counts: Vec<(String, usize)> = Vec::new();
    let mut lines = before.split('\n').peekable();
    let mut current = "";
    while let Some(line) = lines.next() {
        if lines.peek().is_none() {
            current = line;
            break;
        }
        if let Some(header) = header(line, &mut counts) {
            table = header;
        }
    }
    let mut keys = inline_keys(current);
    if !table.is_empty() {
        keys.insert(0, table);
    }
    (!keys.is_empty()).then(|| keys.join("."))
}

/// The path of a table header line (`[a.b]`, or `[[a.b]]` counted into `a.b[n]`).
fn header(line: &str, counts: &mut Vec<(String, usize)>) -> Option<String> {
    let line = line.split('#').next().unwrap_or("").trim();
    if let Some(name) = line.strip_prefix("[[").and_then(|l| l.strip_suffix("]]")) {
        let name = name.trim().to_string();
        let index = match counts.iter_mut().find(|(n, _)| *n == name) {
            Some((_, c)) => {
                *c += 1;
                *c - 1
            }
            None => {
                counts.push((name.clone(), 1));
                0
            }
        };
        return Some(item(&name, index));
    }
    let name = line.strip_prefix('[').and_then(|l| l.strip_suffix(']'))?;
    Some(name.trim().to_string())
}

/// The keys open at the end of `prefix` (a line cut at the offending text), through inline
/// tables: `guide = { through = "C", dir = ` gives `guide.dir`.
fn inline_keys(prefix: &str) -> Vec<String> {
    let mut open: Vec<String> = Vec::new();
    let mut depth = 0usize;
    let mut word = String::new();
    let mut in_string = false;
    for ch in prefix.chars() {
        match ch {
            '"' => in_string = !in_string,
            _ if in_string => {}
            '{' => {
                depth += 1;
                word.clear();
            }
            '}' => depth = depth.saturating_sub(1),
            ',' => word.clear(),
            '=' => {
                open.truncate(depth);
                open.push(word.trim().to_string());
                word.clear();
            }
            c => word.push(c),
        }
    }
    let mut keys = open;
    keys.retain(|k| !k.is_empty());
    keys
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn key_path_reads_headers_and_inline_tables() {
        let text = "[a]\nx = 1\n[[g]]\ny = 2\n[[g]]\nguide = { through = \"C\", dir = \"q\" }\n";
        let offset = text.find("\"q\"").unwrap_or(0);
        assert_eq!(key_path_at(text, offset).as_deref(), Some("g[1].guide.dir"));
        assert_eq!(line_column(text, offset), (6, 32));
    }
}
