//! CSV read by the `csv` crate (RFC 4180: a quoted cell may hold commas): the project's stored
//! tables (the reference sets, the pull-off and finite-size studies under `data/reference/`),
//! each row a map from the header's column names to its cells ([`rows`]), and the files a user
//! gives, each record with its line for the error messages ([`records`]). `#` lines and blank
//! lines are skipped, cells trimmed.

use std::collections::HashMap;

/// One row of a table: column name → cell.
pub(crate) type Row = HashMap<String, String>;

/// The rows of `text` under its first (header) line; a row shorter than the header lacks the
/// last columns.
pub(crate) fn rows(text: &str) -> Vec<Row> {
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .flexible(true)
        .from_reader(text.as_bytes());
    let header: Vec<String> = reader
        .headers()
        .map(|h| h.iter().map(str::to_string).collect())
        .unwrap_or_default();
    reader
        .records()
        .map_while(Result::ok)
        .map(|record| header.iter().cloned().zip(record.iter().map(str::to_string)).collect())
        .collect()
}

/// A record of a CSV file a user gives.
pub(crate) struct Record<'a> {
    /// Its line (1-based).
    pub line: usize,
    /// That line as written, trimmed (an error shows it).
    pub text: &'a str,
    /// Its cells, trimmed and unquoted.
    pub cells: Vec<String>,
}

/// The records of `text`, the header's first; a line of spaces is skipped as a blank one.
pub(crate) fn records(text: &str) -> Vec<Record<'_>> {
    let lines: Vec<&str> = text.lines().collect();
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .flexible(true)
        .from_reader(text.as_bytes());
    reader
        .records()
        .map_while(Result::ok)
        .filter(|r| !(r.len() == 1 && r[0].is_empty()))
        .map(|r| {
            // the reader's position is where it started reading the record, `#` lines and
            // empty lines before it included: the record's own line is the next one with text
            let mut line = r.position().map_or(1, |p| p.line() as usize).max(1);
            while lines.get(line - 1).is_some_and(|l| l.starts_with('#') || l.is_empty()) {
                line += 1;
            }
            Record {
                line,
                text: lines.get(line.saturating_sub(1)).map_or("", |l| l.trim()),
                cells: r.iter().map(str::to_string).collect(),
            }
        })
        .collect()
}

/// The number in `row`'s column `key` (`inf` reads as infinite); NaN where the column is
/// missing or its cell is not a number.
pub(crate) fn number(row: &Row, key: &str) -> f64 {
    row.get(key).and_then(|s| s.parse().ok()).unwrap_or(f64::NAN)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_skip_comments_and_blank_lines_and_trim_cells() {
        let text = "# a note, with a comma\nname,p,q\n\nsystem-2, 1e-3 ,inf\n# between\nsystem-1,x\n";
        let r = rows(text);
        assert_eq!(r.len(), 2);
        assert_eq!(r[0]["name"], "system-2");
        assert_eq!(number(&r[0], "p"), 1e-3);
        assert_eq!(number(&r[0], "q"), f64::INFINITY);
        assert!(number(&r[1], "p").is_nan(), "a cell that is not a number");
        assert!(number(&r[1], "q").is_nan(), "a short row's missing column");
        assert!(number(&r[0], "absent").is_nan());
    }

    #[test]
    fn records_keep_their_lines_and_unquote_cells() {
        let text = "# note\np,a_r\n\n   \n1e-3, 0.5\n# a, b\n\n\"2e-3\",\"0,6\"\n";
        let r = records(text);
        let lines: Vec<usize> = r.iter().map(|x| x.line).collect();
        assert_eq!(lines, [2, 5, 8]);
        assert_eq!(r[0].cells, ["p", "a_r"]);
        assert_eq!(
            (r[1].text, r[1].cells.clone()),
            ("1e-3, 0.5", vec!["1e-3".to_string(), "0.5".into()])
        );
        assert_eq!(r[2].cells, ["2e-3", "0,6"]);
    }
}
