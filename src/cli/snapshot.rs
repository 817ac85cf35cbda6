//! `zieglerlab snapshot`: the app (or one panel) rendered headlessly to a PNG
//! after a given simulated time, optionally at a step of a lesson.

use anyhow::Result;
use zieglerlab::format::Shown;

use zieglerlab::app::{Action, Command, Settings, Tab, ZieglerApp};
use zieglerlab::i18n::Language;
use zieglerlab::lesson::{Lesson, built_in};

use super::headless::{Look, Size, render_frames};
use super::output::{check_output, write_png};
use super::{EngineArg, ModelArgs, progress_bar};

#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    model: ModelArgs,
    /// Simulated time before the picture, in s.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    time: f64,
    #[arg(long, value_enum, default_value_t = EngineArg::Rapier)]
    engine: EngineArg,
    /// Image size in pixels, `WIDTHxHEIGHT`.
    #[arg(long, default_value = "1280x800", allow_hyphen_values = true)]
    size: Size,
    #[command(flatten)]
    look: Look,
    /// A lesson to show (for a handout): a built-in one by name (see
    /// `zieglerlab lesson`, with or without `.ron`) or a lesson file. It is
    /// opened on `--preset` as the window opens it, and `--time` runs from
    /// its step `--step`.
    #[arg(long, value_name = "NAME|FILE")]
    lesson: Option<String>,
    /// The lesson's step to show, from 1.
    #[arg(long, requires = "lesson", allow_hyphen_values = true)]
    step: Option<i64>,
    #[arg(long)]
    out: std::path::PathBuf,
}

/// The lesson named `name` (a built-in one, with or without `.ron`) or in
/// the file `name`.
fn lesson_named(name: &str, language: Language) -> Result<Lesson> {
    let tabs = Tab::ids();
    let lessons = built_in(language);
    let built_in = lessons
        .iter()
        .find(|(file, _)| *file == name || file.strip_suffix(".ron") == Some(name));
    match built_in {
        Some((_, text)) => Ok(Lesson::read(text, &tabs)?),
        None => Ok(Lesson::read_file(std::path::Path::new(name), &tabs)?),
    }
}

/// `app` with `lesson` open at step `step` (from 1), as Page Down takes the
/// window there.
fn open_at_step(app: &mut ZieglerApp, lesson: Lesson, step: Option<i64>) -> Result<()> {
    let steps = lesson.steps.len();
    let step = step.unwrap_or(1);
    let Some(index) = usize::try_from(step)
        .ok()
        .filter(|&s| (1..=steps).contains(&s))
        .map(|s| s - 1)
    else {
        anyhow::bail!("step = {step}: the lesson has steps 1 to {steps}");
    };
    app.apply(Action::LessonOpen(Box::new(lesson)));
    for _ in 0..index {
        app.apply(Action::Command(Command::LessonNext));
    }
    Ok(())
}

pub fn run(args: &Args) -> Result<()> {
    check_output(&args.out, true)?;
    args.look.check(args.size)?;
    let (name, model) = args.model.build_for_the_window()?;
    let time = args.time;
    if !(time.is_finite() && (0.0..=1.0e5).contains(&time)) {
        anyhow::bail!(
            "time = {}: must be a number of seconds in [0, 100000]",
            Shown(time)
        );
    }
    let settings = Settings {
        preset: name,
        model,
        engine: args.engine.into(),
        speed: 1.0,
        projector: args.look.projector,
    };
    let language = args.look.language();
    let lesson = args
        .lesson
        .as_deref()
        .map(|name| lesson_named(name, language))
        .transpose()?;
    let mut app = ZieglerApp::new(settings)?;
    app.apply(Action::Language(language));
    if let Some(lesson) = lesson {
        open_at_step(&mut app, lesson, args.step)?;
    }
    // Whole 1/60 s frames, as the app advances: the same picture every time.
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "time is checked to lie in [0, 100000] s: at most 6e6 frames"
    )]
    let frames = (time * 60.0).round() as u64;
    let progress = progress_bar(frames, "simulated frames");
    for frame in 0..frames {
        app.advance(1.0 / 60.0);
        if frame % 600 == 0 {
            progress.set_position(frame);
        }
    }
    progress.finish_and_clear();
    let panel = args.look.panel();
    let mut image = None;
    render_frames(
        app,
        panel,
        args.size,
        args.look.scale,
        1,
        |_, _| {},
        |_, frame| {
            image = Some(frame);
            Ok(())
        },
    )?;
    match image {
        Some(image) => write_png(&args.out, &image),
        None => anyhow::bail!("rendering gave no picture"),
    }
}
