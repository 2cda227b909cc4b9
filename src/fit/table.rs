//! The project's stored CSV tables (the reference sets, the pull-off and finite-size studies
//! under `data/reference/`) read by the `csv` crate: `#` lines and blank lines are skipped,
//! cells trimmed, and each row is a map from the header's column names to its cells.

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
}
