//! Where a mouse click lands (`--mouse`): on a chart panel, on a knob's row of the parameter
//! panel, or elsewhere, on the layout the view draws ([`super::screen_of`]). The event loop asks
//! this before handing the click to the update, which knows no geometry.

use crate::tui::model::app::{App, Overlay};
use crate::tui::model::msg::Target;
use crate::tui::view::palette::Palette;
use crate::tui::view::screen_of;
use ratatui::layout::{Position, Rect};

/// What lies under the cell (`col`, `row`) of a terminal of `area`.
pub fn hit(app: &App, area: Rect, col: u16, row: u16) -> Target {
    let at = Position::new(col, row);
    if app.ui.overlay != Overlay::None || !area.contains(at) {
        return Target::Elsewhere;
    }
    let (_, scr) = screen_of(app, area, Palette { color: false });
    if app.ui.zoom {
        let body = scr.charts.iter().fold(scr.panel, |u, (r, _)| u.union(*r));
        return if body.contains(at) {
            Target::Chart(app.ui.focus.min(2))
        } else {
            Target::Elsewhere
        };
    }
    if let Some((_, i)) = scr.charts.iter().find(|(r, _)| r.contains(at)) {
        return Target::Chart(*i);
    }
    // the panel's knobs are its first rows, inside its border
    let first = scr.panel.y + 1;
    if scr.panel.contains(at) && row >= first && usize::from(row - first) < app.knob_rows().len() {
        return Target::Knob(usize::from(row - first));
    }
    Target::Elsewhere
}

#[cfg(test)]
mod tests {
    use super::*;
    use asperity::input::preset::Preset;

    #[test]
    fn a_click_finds_the_chart_or_the_knob_under_it() {
        let a = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        let area = Rect::new(0, 0, 200, 60);
        let (_, scr) = screen_of(&a, area, Palette { color: false });
        assert_eq!(scr.charts.len(), 3);
        for (r, i) in &scr.charts {
            assert_eq!(hit(&a, area, r.x + r.width / 2, r.y + r.height / 2), Target::Chart(*i));
        }
        let p = scr.panel;
        assert_eq!(hit(&a, area, p.x + 2, p.y + 1), Target::Knob(0));
        assert_eq!(hit(&a, area, p.x + 2, p.y + 3), Target::Knob(2));
        // the panel's border, its read-outs, the title row and the status rows are no target
        assert_eq!(hit(&a, area, p.x + 2, p.y), Target::Elsewhere);
        assert_eq!(
            hit(&a, area, p.x + 2, p.y + 1 + a.knob_rows().len() as u16),
            Target::Elsewhere
        );
        assert_eq!(hit(&a, area, 100, 0), Target::Elsewhere);
        assert_eq!(hit(&a, area, 100, 59), Target::Elsewhere);
        assert_eq!(hit(&a, area, 300, 10), Target::Elsewhere);
    }

    #[test]
    fn a_zoomed_chart_takes_every_click_on_the_body_and_an_overlay_none() {
        let mut a = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
        let area = Rect::new(0, 0, 80, 24);
        a.ui.zoom = true;
        a.ui.focus = 1;
        assert_eq!(hit(&a, area, 3, 5), Target::Chart(1));
        a.ui.zoom = false;
        a.ui.overlay = Overlay::Help;
        assert_eq!(hit(&a, area, 3, 5), Target::Elsewhere);
    }
}
