//! The tools in the sidebar's heading, used as a person uses them
//! (`egui_kittest`): within reach in a 1024x768 window, the keys help whole,
//! and settings pasted from the system clipboard.

use crate::common::message_line;
use eframe::egui;
use egui_kittest::kittest::Queryable as _;
use zieglerlab::app::{Action, Command, Settings, Tab, ZieglerApp};
use zieglerlab::i18n::{Language, words};
use zieglerlab::model::PresetId;

use crate::app_input::harness_at;

/// Opens the share menu and asks for a paste from the clipboard; the
/// window answers, in the next frame, with `answer` (nothing: an empty
/// clipboard). The frames after are run.
pub(crate) fn paste_from_clipboard(app: &mut ZieglerApp, answer: Option<&str>) {
    let mut harness = harness_at(app, [1280.0, 800.0]);
    harness.get_by_label("share").click();
    harness.run();
    harness.get_by_label("paste from clipboard").click();
    harness.step();
    match answer {
        Some(text) => {
            harness.event(egui::Event::Paste(text.to_owned()));
            harness.step();
            harness.run();
        }
        None => {
            for _ in 0..6 {
                harness.step();
            }
        }
    }
}

/// At 1024x768 in normal mode every tool is on the screen without
/// scrolling (share, record and keys used to sit below the fold), and the
/// keys help shows each line whole inside the window (it was cut at the
/// sidebar's edge: "R reset: a fresh run from the stan").
#[test]
fn the_tools_are_in_reach_and_the_keys_help_whole_at_1024x768() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1024.0, 768.0));
    let mut harness = harness_at(&mut app, [1024.0, 768.0]);
    for label in ["share", "record", "keys", "projector (P)", "overlay"] {
        let rect = harness.get_by_label(label).rect();
        assert!(screen.contains_rect(rect), "{label} at {rect:?}");
    }
    harness.get_by_label("keys").click();
    harness.run();
    for command in Command::ALL {
        let english = words(Language::English);
        if command.key_names(english).is_empty() {
            continue;
        }
        let tooltip = command.tooltip(english);
        let line = harness.get_by_label(&tooltip);
        assert!(
            screen.contains_rect(line.rect()),
            "{}: {:?}",
            command.tooltip(english),
            line.rect()
        );
    }
}

/// "paste from clipboard" asks the window for the clipboard's text and
/// takes it as settings, keeping the open tab; text that is not settings
/// is refused by name, and a clipboard with no text is said to have none.
#[test]
fn settings_are_pasted_from_the_clipboard() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    app.apply(Action::Tab(Tab::Histories));
    paste_from_clipboard(&mut app, Some("preset = ziegler-1952\nload = 1.5\n"));
    assert_eq!(app.state().settings().preset, PresetId::Ziegler1952);
    assert!((app.state().model().load_p() - 1.5).abs() < 1e-12);
    assert_eq!(app.layout().tab, Tab::Histories, "a paste keeps the tab");
    paste_from_clipboard(&mut app, Some("hello, world"));
    let said = message_line(&app);
    assert!(said.contains("pasted settings"), "{said}");
    assert_eq!(app.state().settings().preset, PresetId::Ziegler1952);
    // No answer: the clipboard holds no text.
    paste_from_clipboard(&mut app, None);
    let said = message_line(&app);
    assert!(said.contains("the clipboard holds no text"), "{said}");
}

/// Projector mode with each tab, on a small projector, a laptop and a full
/// HD projector: every tab is on the screen once, never twice (at 1920x1080
/// a tab shown in the column's place was drawn again below the tab bar, and
/// the column was nowhere), and on the full HD one the column is there too.
/// The root locus tab shows its plots below the tab bar, or the complex
/// plane beside the column and a note below.
#[test]
fn in_projector_mode_every_tab_is_shown_once() {
    for size in [[1024.0, 768.0], [1280.0, 800.0], [1920.0, 1080.0]] {
        for tab in Tab::all() {
            let mut app = ZieglerApp::new(Settings {
                projector: true,
                ..Settings::default()
            })
            .unwrap();
            app.show_tab(tab);
            // The post-critical tab's diagram, computed in the background.
            app.complete_background_work(tab);
            let harness = harness_at(&mut app, size);
            let bars = harness.query_all_by_label("save PNG...").count();
            let at = format!("{} at {size:?}", tab.title(words(Language::English)));
            // A full HD projector has room for the column and any tab: the
            // tab below the tab bar, not in the column's place above it.
            if size[1] >= 1080.0 {
                let tab_bar = harness.get_by_label("time histories").rect().bottom();
                let tab_top = harness.get_by_label("save PNG...").rect().top();
                assert!(
                    tab_top > tab_bar,
                    "{at}: the tab at {tab_top}, above the tab bar"
                );
            }
            if tab == Tab::Locus {
                let beside = harness
                    .query_by_label_contains("The root locus is beside the column")
                    .is_some();
                assert_eq!(bars, usize::from(!beside), "{at}: {bars} tab bars");
            } else {
                assert_eq!(bars, 1, "{at}: {bars} tab bars");
            }
        }
    }
}

/// On a desktop with no file dialog (no portal, no zenity: this machine),
/// The app on its time histories after a second of the run, for a save.
fn app_with_a_run() -> ZieglerApp {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    // Whatever the desktop the tests run on: no dialog of its own.
    app.type_paths();
    app.apply(Action::Tab(Tab::Histories));
    for _ in 0..60 {
        app.state_mut().advance(1.0 / 60.0);
    }
    app
}

/// Clicks "save CSV..." and waits for the window to type the path in (no
/// desktop dialog opens here); the path it proposes.
fn open_typed_save(harness: &mut egui_kittest::Harness<'_>) -> String {
    harness.get_by_label("save CSV...").click();
    for _ in 0..100 {
        harness.step();
        std::thread::sleep(std::time::Duration::from_millis(20));
        if let Some(node) = harness.query_by_label("save as path") {
            return node.value().unwrap_or_default();
        }
    }
    panic!("no window to type the path in");
}

/// Selects the typed path's text and types `path` in its place.
fn type_path(harness: &mut egui_kittest::Harness<'_>, path: &str) {
    harness.get_by_label("save as path").click();
    harness.run_steps(2);
    harness.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    harness.run_steps(2);
    harness.get_by_label("save as path").type_text(path);
    harness.run_steps(2);
}

/// Frames until the message line says something starting with `start`
/// (the file is written off the window's thread).
fn until_said(harness: &mut egui_kittest::Harness<'_>, start: &str) {
    for _ in 0..200 {
        harness.step();
        if harness.query_by_label_contains(start).is_some() {
            return;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    panic!("never said {start:?}");
}

/// "save CSV..." opens a window to type the path in, the folder and a
/// suggested name filled in; a typed path gets the table, and "cancel"
/// saves nothing and says so. (It said only that no file was chosen, and
/// there was no way to save.)
#[test]
fn a_save_without_a_desktop_dialog_takes_a_typed_path() {
    let mut app = app_with_a_run();
    let folder = tempfile::tempdir().unwrap();
    let out = folder.path().join("run.csv");
    {
        let mut harness = harness_at(&mut app, [1280.0, 800.0]);
        let typed = open_typed_save(&mut harness);
        assert!(typed.ends_with("zieglerlab-history.csv"), "{typed}");
        type_path(&mut harness, out.to_str().unwrap());
        harness.get_by_label("save").click();
        until_said(&mut harness, "saved ");
    }
    let text = std::fs::read_to_string(&out).expect("the table written to the typed path");
    assert!(text.starts_with("t,phi1,phi2"), "{text}");
}

/// The typed save asks before it replaces a file, refuses a FIFO (writing
/// to one froze the window for good) and a missing folder, and keeps the
/// keys in its field after Enter on a refused path: an "r" typed on goes
/// into the path, not to the window (it reset the run about to be saved).
#[cfg(unix)]
#[test]
fn the_typed_save_asks_before_replacing_and_refuses_a_fifo() {
    let mut app = app_with_a_run();
    let folder = tempfile::tempdir().unwrap();
    let kept = folder.path().join("kept.csv");
    std::fs::write(&kept, "the user's table\n").unwrap();
    let fifo = folder.path().join("fifo");
    assert!(
        std::process::Command::new("mkfifo")
            .arg(&fifo)
            .status()
            .expect("mkfifo (coreutils) runs")
            .success()
    );
    {
        let mut harness = harness_at(&mut app, [1280.0, 800.0]);
        open_typed_save(&mut harness);
        type_path(&mut harness, fifo.to_str().unwrap());
        assert!(
            harness
                .query_by_label_contains("a pipe or a device")
                .is_some()
        );
        // Enter on a missing folder: refused, the field keeps the keys.
        type_path(&mut harness, "/no-such-folder/x.csv");
        assert!(
            harness
                .query_by_label_contains("its folder does not exist")
                .is_some()
        );
        harness.key_press(egui::Key::Enter);
        harness.run_steps(2);
        harness.get_by_label("save as path").type_text("r");
        harness.run_steps(2);
        let field = harness.get_by_label("save as path");
        assert!(field.is_focused(), "the field lost the keys");
        assert_eq!(field.value().as_deref(), Some("/no-such-folder/x.csvr"));
        // An existing file: asked, not replaced; a second save replaces it.
        type_path(&mut harness, kept.to_str().unwrap());
        harness.get_by_label("save").click();
        harness.run_steps(3);
        assert!(
            harness
                .query_by_label_contains("exists: replace it?")
                .is_some()
        );
        assert_eq!(
            std::fs::read_to_string(&kept).unwrap(),
            "the user's table\n"
        );
        harness.get_by_label("replace").click();
        until_said(&mut harness, "saved ");
    }
    assert!(
        std::fs::read_to_string(&kept)
            .unwrap()
            .starts_with("t,phi1,phi2")
    );
}

/// A long paste (300 lines) stays in a box that scrolls: the menu's
/// button under the box stays inside a 1024x768 window (the box grew past
/// the window's foot and took the button with it).
#[test]
fn a_long_paste_scrolls_inside_the_share_menu() {
    let mut app = ZieglerApp::new(Settings::default()).unwrap();
    let mut long = String::new();
    for k in 1..=300 {
        std::fmt::Write::write_fmt(&mut long, format_args!("# pasted line {k}\n")).unwrap();
    }
    let screen = egui::Rect::from_min_size(egui::Pos2::ZERO, egui::vec2(1024.0, 768.0));
    let mut harness = harness_at(&mut app, [1024.0, 768.0]);
    harness.get_by_label("share").click();
    harness.run();
    harness.get_by_label("paste from clipboard").click();
    harness.step();
    harness.event(egui::Event::Paste(long));
    harness.run_steps(4);
    let take = harness.get_by_label("take the text above").rect();
    assert!(screen.contains_rect(take), "the button at {take:?}");
    let copy = harness.get_by_label("copy settings").rect();
    assert!(screen.contains_rect(copy), "the menu's top at {copy:?}");
}
