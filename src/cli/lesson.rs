//! `zieglerlab lesson`: checks a lesson file (the first problem, with its
//! line and what was expected), or lists the lessons built in.

use std::io::Write;

use anyhow::Result;

use zieglerlab::lesson::{BUILT_IN, Lesson};

#[derive(clap::Args, Debug)]
pub struct Args {
    /// The lesson file to check.
    #[arg(long, value_name = "FILE")]
    check: Option<std::path::PathBuf>,
}

pub fn run(args: &Args, out: &mut impl Write) -> Result<()> {
    let Some(path) = &args.check else {
        writeln!(out, "built-in lessons (check your own with --check FILE):")?;
        for (name, text) in BUILT_IN {
            let lesson = Lesson::read(text, &zieglerlab::app::Tab::ids())?;
            writeln!(
                out,
                "  {name}: {} ({} steps)",
                lesson.title,
                lesson.steps.len()
            )?;
        }
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
