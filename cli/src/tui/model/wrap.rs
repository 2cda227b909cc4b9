//! Word wrap of the caption and help text, and the most rows a caption can take (which bounds
//! its scroll, a state the update keeps).

use ratatui::text::Span;

/// Smallest usable terminal (columns, rows).
pub const MIN_SIZE: (u16, u16) = (60, 20);
/// Rows of the caption box's borders.
pub const CAPTION_BORDER_ROWS: u16 = 2;

/// Display width of a text.
fn width(s: &str) -> usize {
    Span::raw(s).width()
}

/// Greedy word wrap to `cols` columns (a word longer than a row is cut into rows).
pub fn wrap(text: &str, cols: usize) -> Vec<String> {
    let cols = cols.max(1);
    let mut out = Vec::new();
    for para in text.lines() {
        let mut line = String::new();
        for word in para.split_whitespace() {
            let w = width(word);
            let need = if line.is_empty() { w } else { width(&line) + 1 + w };
            if need <= cols {
                if !line.is_empty() {
                    line.push(' ');
                }
                line.push_str(word);
                continue;
            }
            if !line.is_empty() {
                out.push(std::mem::take(&mut line));
            }
            // a word wider than the row: cut it
            let mut rest = word.to_string();
            while width(&rest) > cols {
                let cut: String = rest
                    .chars()
                    .scan(0, |acc, c| {
                        *acc += width(&c.to_string());
                        (*acc <= cols).then_some(c)
                    })
                    .collect();
                rest = rest[cut.len()..].to_string();
                out.push(cut);
            }
            line = rest;
        }
        out.push(line);
    }
    out
}

/// Most rows the caption `text` can take at any terminal width the explorer runs at (it
/// bounds the caption's scroll).
pub fn caption_rows_at_most(text: &[String]) -> usize {
    let cols = usize::from(MIN_SIZE.0 - CAPTION_BORDER_ROWS);
    text.iter().map(|l| wrap(l, cols).len()).sum()
}
