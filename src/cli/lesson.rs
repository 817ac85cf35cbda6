//! `zieglerlab lesson`: checks a lesson file (the first problem, with its
//! line and what was expected), or lists the lessons built in.

use std::io::Write;

use anyhow::Result;

use zieglerlab::i18n::Language;
use zieglerlab::lesson::{BUILT_IN, Lesson, built_in};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The lesson file to check.
    #[arg(long, value_name = "FILE")]
    check: Option<std::path::PathBuf>,
}

pub fn run(args: &Args, out: &mut impl Write) -> Result<()> {
    let Some(path) = &args.check else {
        writeln!(out, "built-in lessons (check your own with --check FILE):")?;
        let tabs = zieglerlab::app::Tab::ids();
        for (name, text) in BUILT_IN {
            let lesson = Lesson::read(text, &tabs)?;
            writeln!(
                out,
                "  {name}: {} ({} steps)",
                lesson.title,
                lesson.steps.len()
            )?;
        }
        // Every language's lessons are read and checked as the English ones.
        let mut codes = Vec::new();
        for language in Language::CHOSEN_FROM.into_iter().skip(1) {
            for (name, text) in built_in(language) {
                Lesson::read(text, &tabs)
                    .map_err(|error| anyhow::anyhow!("{name} ({language}): {error}"))?;
            }
            codes.push(language.code());
        }
        writeln!(
            out,
            "each also in {}, every one read and checked",
            codes.join(", ")
        )?;
        return Ok(());
    };
    let lesson = Lesson::read_file(path, &zieglerlab::app::Tab::ids())?;
    writeln!(
        out,
        "{}: ok: \"{}\", {} steps, from every preset, forward and back",
        path.display(),
        lesson.title,
        lesson.steps.len()
    )?;
    Ok(())
}
