//! A fault of the compute worker (a panic, caught, see `effects::worker`) reaches the
//! explorer as a message: the panel and the charts say what failed instead of "computing…",
//! the state is no longer busy, and q, Esc and Ctrl-C still do what they do. Also the weakest
//! surface energy the theory refuses to resolve (γ_s = 1e-320 J/m²) is solved, not faulted.

use asperity::input::preset::Preset;
use asperity_cli::tui::app::App;
use asperity_cli::tui::base::protocol::Reply;
use asperity_cli::tui::drive::{compute_now, Caches};
use asperity_cli::tui::model::command::Command;
use asperity_cli::tui::model::msg::Msg;
use asperity_cli::tui::update::update;
use asperity_cli::tui::view;
use ratatui::backend::TestBackend;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::Terminal;

fn app() -> App {
    let mut a = App::new("system-1", Preset::resolve("system-1").unwrap()).unwrap();
    a.ui.show_timing = false;
    a.ui.color = false;
    a
}

fn render(app: &App) -> String {
    let mut t = Terminal::new(TestBackend::new(120, 40)).unwrap();
    t.draw(|f| view::draw(f, app)).unwrap();
    t.backend().to_string()
}

fn quits(a: &mut App, code: KeyCode, mods: KeyModifiers) -> bool {
    update(a, Msg::Key(KeyEvent::new(code, mods)))
        .iter()
        .any(|c| matches!(c, Command::Quit))
}

#[test]
fn a_worker_fault_is_shown_and_the_explorer_stays_responsive() {
    let mut a = app();
    let req = a.take_request().expect("the first request");
    assert!(a.jobs.busy());
    assert!(render(&a).contains("computing"));
    let _ = update(
        &mut a,
        Msg::Reply(Box::new(Reply::Fault {
            gen: req.gen,
            message: "internal fault: injected".into(),
        })),
    );
    assert!(!a.jobs.busy());
    let screen = render(&a);
    assert!(!screen.contains("computing"), "{screen}");
    assert!(screen.contains("failed"), "{screen}");
    assert!(screen.contains("internal fault"), "{screen}");
    // Esc cancels and never quits; q and Ctrl-C quit
    assert!(!quits(&mut a, KeyCode::Esc, KeyModifiers::NONE));
    assert!(quits(&mut a, KeyCode::Char('c'), KeyModifiers::CONTROL));
    assert!(quits(&mut a, KeyCode::Char('q'), KeyModifiers::NONE));
}

#[test]
fn the_weakest_surface_energy_is_solved_in_the_explorer() {
    let mut a = app();
    a.params.scene = a.params.scene.clone().with_surface_energy_j_m2(1e-320).unwrap();
    compute_now(&mut a, &mut Caches::default());
    let point = a.results.point().expect("a point");
    assert!(point.is_ok(), "{point:?}");
    assert!(!render(&a).contains("failed"));
}
