//! `zieglerlab completions SHELL` and `zieglerlab manual`: the shell's
//! completions and the man page, written from the command line's own
//! description (`clap_complete`, `clap_mangen`), so they never fall behind it.

use std::io::Write;

use anyhow::{Context, Result};

/// The shells completions are written for.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum Shell {
    Bash,
    Zsh,
    Fish,
}

#[derive(clap::Args, Debug)]
pub struct CompletionsArgs {
    /// The shell: bash, zsh or fish.
    #[arg(value_enum)]
    shell: Shell,
}

#[derive(clap::Args, Debug)]
pub struct ManualArgs {
    /// Write every page into DIR (zieglerlab.1 and one page for each
    /// subcommand, zieglerlab-critical.1, ...) instead of zieglerlab.1 to
    /// standard output.
    #[arg(long, value_name = "DIR")]
    dir: Option<std::path::PathBuf>,
}

/// Writes the completions of `command` for the shell asked for.
pub fn completions(
    args: &CompletionsArgs,
    command: &mut clap::Command,
    out: &mut impl Write,
) -> Result<()> {
    let shell = match args.shell {
        Shell::Bash => clap_complete::Shell::Bash,
        Shell::Zsh => clap_complete::Shell::Zsh,
        Shell::Fish => clap_complete::Shell::Fish,
    };
    let name = command.get_name().to_owned();
    let mut text = Vec::new();
    clap_complete::generate(shell, command, name, &mut text);
    out.write_all(&text).context("writing the completions")
}

/// Writes the man page of `command` (section 1, roff) to `out`, or with
/// `--dir` every page into that folder, naming each file written.
pub fn manual(args: &ManualArgs, command: clap::Command, out: &mut impl Write) -> Result<()> {
    let Some(dir) = &args.dir else {
        let mut page = Vec::new();
        clap_mangen::Man::new(command)
            .render(&mut page)
            .context("rendering the man page")?;
        return out.write_all(&page).context("writing the man page");
    };
    if !dir.is_dir() {
        anyhow::bail!("--dir {}: not a folder", dir.display());
    }
    // clap_mangen names the pages: they are written into a fresh folder
    // inside `dir` (removed however the command ends) and moved out of it,
    // so the names said are the files written, whatever its naming.
    let in_dir = |what: &str, error: &dyn std::fmt::Display| {
        anyhow::anyhow!("--dir {}: {what}: {error}", dir.display())
    };
    let staging = zieglerlab::files::StagingFolder::new_in(dir, ".zieglerlab-manual")
        .map_err(|e| in_dir("takes no new folder", &e))?;
    clap_mangen::generate_to(command, staging.path())
        .map_err(|e| in_dir("the pages could not be made", &e))?;
    let mut pages = std::fs::read_dir(staging.path())
        .and_then(|entries| {
            entries
                .map(|entry| entry.map(|e| e.file_name()))
                .collect::<Result<Vec<_>, _>>()
        })
        .map_err(|e| in_dir("the pages could not be made", &e))?;
    pages.sort();
    // Every page in the way is found before any is moved, so a refusal
    // leaves the folder as it was.
    for page in &pages {
        let target = dir.join(page);
        let shown = page.to_string_lossy();
        if std::fs::symlink_metadata(&target).is_ok_and(|m| m.is_dir()) {
            anyhow::bail!(
                "--dir {}: {shown} is a folder, in the way of that page; no page was written",
                dir.display()
            );
        }
        if let Some(why) = zieglerlab::files::protected(&target) {
            anyhow::bail!(
                "--dir {}: {shown}: {why}; no page was written",
                dir.display()
            );
        }
    }
    for (done, page) in pages.iter().enumerate() {
        let target = dir.join(page);
        if let Err(error) = std::fs::rename(staging.path().join(page), &target) {
            let what = format!(
                "{} could not be written ({done} of {} pages were written before it, the rest were not)",
                page.to_string_lossy(),
                pages.len()
            );
            return Err(in_dir(&what, &error));
        }
        writeln!(out, "{}", target.display())?;
    }
    Ok(())
}
