//! The desktop's conventions: the desktop entry passes the freedesktop.org
//! checker, and the shells' completions and the man page name every
//! subcommand the help lists.

use std::process::Command;

use crate::cli::run;

/// The subcommands as `zieglerlab --help` lists them (its own words, not
/// clap's description that the completions are made from).
fn subcommands() -> Vec<String> {
    let help = String::from_utf8(run(&["--help"]).stdout).unwrap();
    let listed: Vec<String> = help
        .lines()
        .skip_while(|line| !line.starts_with("Commands:"))
        .skip(1)
        .take_while(|line| line.starts_with("  "))
        .filter_map(|line| line.split_whitespace().next().map(str::to_owned))
        .filter(|name| name != "help")
        .collect();
    assert!(listed.len() >= 13, "{help}");
    listed
}

/// desktop-file-validate (Debian's desktop-file-utils, installed by
/// `.ci/run`) finds nothing wrong with the entry, which names the icon
/// beside it.
#[test]
fn the_desktop_entry_is_valid() {
    let entry = concat!(env!("CARGO_MANIFEST_DIR"), "/assets/zieglerlab.desktop");
    let checked = crate::common::output_within(
        Command::new("desktop-file-validate").arg(entry),
        std::time::Duration::from_mins(1),
        "desktop-file-validate",
        "desktop-file-validate (package desktop-file-utils; .ci/run installs it)",
    );
    let said = String::from_utf8_lossy(&checked.stdout).into_owned()
        + &String::from_utf8_lossy(&checked.stderr);
    assert!(checked.status.success() && said.trim().is_empty(), "{said}");
    let text = std::fs::read_to_string(entry).unwrap();
    assert!(text.lines().any(|line| line == "Exec=zieglerlab"), "{text}");
    assert!(text.lines().any(|line| line == "Icon=zieglerlab"), "{text}");
    for icon in ["zieglerlab.svg", "zieglerlab.png"] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("assets")
            .join(icon);
        assert!(path.is_file(), "{}", path.display());
    }
}

/// Each shell's completions name every subcommand; an unknown shell is
/// refused with the ones there are.
#[test]
fn the_completions_name_every_subcommand() {
    let names = subcommands();
    for shell in ["bash", "zsh", "fish"] {
        let output = run(&["completions", shell]);
        assert!(output.status.success(), "{shell}");
        let text = String::from_utf8(output.stdout).unwrap();
        for name in &names {
            assert!(text.contains(name.as_str()), "{shell}: {name}");
        }
        // And the options of a subcommand.
        assert!(text.contains("load-max"), "{shell}: critical's --load-max");
    }
    let refused = run(&["completions", "tcsh"]);
    assert_eq!(refused.status.code(), Some(2));
    let said = String::from_utf8(refused.stderr).unwrap();
    assert!(said.contains("bash") && said.contains("fish"), "{said}");
}

/// The man page is roff for section 1 and lists every subcommand; with
/// --dir every subcommand gets its own page, each file named on stdout.
#[test]
fn the_man_pages_cover_every_subcommand() {
    let names = subcommands();
    let page = String::from_utf8(run(&["manual"]).stdout).unwrap();
    assert!(
        page.starts_with(".ie") || page.contains(".TH zieglerlab 1"),
        "{page}"
    );
    for name in &names {
        assert!(page.contains(name.as_str()), "{name}");
    }
    let dir = tempfile::tempdir().unwrap();
    let dir_text = dir.path().to_str().unwrap();
    let output = run(&["manual", "--dir", dir_text]);
    assert!(output.status.success(), "{output:?}");
    let written = String::from_utf8(output.stdout).unwrap();
    for name in std::iter::once("zieglerlab".to_owned())
        .chain(names.iter().map(|n| format!("zieglerlab-{n}")))
    {
        let path = dir.path().join(format!("{name}.1"));
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.contains(&format!(".TH {name} 1")), "{name}");
        assert!(written.contains(path.to_str().unwrap()), "{written}");
    }
    // Each file said is a page in the folder, and nothing else is left there.
    let mut held: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|entry| entry.unwrap().path().to_str().unwrap().to_owned())
        .collect();
    held.sort();
    let mut said: Vec<&str> = written.lines().collect();
    said.sort_unstable();
    assert_eq!(held, said);
    let missing = run(&["manual", "--dir", "/nonexistent-folder"]);
    assert_eq!(missing.status.code(), Some(2));
}

/// A page in the way (a folder named as a page) is found before any page
/// is moved: the error names the folder typed and the page, the folder
/// holds what it held, and no staging folder is left.
#[test]
fn a_page_in_the_way_leaves_the_folder_as_it_was() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("zieglerlab-map.1")).unwrap();
    std::fs::write(dir.path().join("zieglerlab.1"), "an older page").unwrap();
    let dir_text = dir.path().to_str().unwrap();
    let output = run(&["manual", "--dir", dir_text]);
    assert_eq!(output.status.code(), Some(2));
    let said = String::from_utf8(output.stderr).unwrap();
    assert!(
        said.contains(&format!("--dir {dir_text}: zieglerlab-map.1 is a folder"))
            && said.contains("no page was written"),
        "{said}"
    );
    assert!(!said.contains(".zieglerlab-manual"), "{said}");
    let mut held: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|entry| entry.unwrap().file_name().into_string().unwrap())
        .collect();
    held.sort();
    assert_eq!(held, ["zieglerlab-map.1", "zieglerlab.1"]);
    let old = std::fs::read_to_string(dir.path().join("zieglerlab.1")).unwrap();
    assert_eq!(old, "an older page");
}
