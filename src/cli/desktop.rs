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
    // inside `dir` and moved out of it, so the names said are the files
    // written, whatever its naming.
    let written_in = |error: std::io::Error| {
        anyhow::Error::new(error).context(format!("writing the man pages into {}", dir.display()))
    };
    let staging = tempfile::Builder::new()
        .prefix(".zieglerlab-manual")
        .tempdir_in(dir)
        .map_err(written_in)?;
    clap_mangen::generate_to(command, staging.path()).map_err(written_in)?;
    let mut pages = std::fs::read_dir(staging.path())
        .and_then(|entries| {
            entries
                .map(|entry| entry.map(|e| e.file_name()))
                .collect::<Result<Vec<_>, _>>()
        })
        .map_err(written_in)?;
    pages.sort();
    for page in pages {
        let target = dir.join(&page);
        std::fs::rename(staging.path().join(&page), &target).map_err(written_in)?;
        writeln!(out, "{}", target.display())?;
    }
    Ok(())
}
