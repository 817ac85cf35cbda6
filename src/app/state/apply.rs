//! The one place the state changes at a person's (or a lesson's) request:
//! each [`Action`] carried out, or handed back when it is the window's own
//! (the tab, a recording).

use super::AppState;
use crate::app::action::{Action, Command};
use crate::lesson::KICK_RAD;

/// The step of the load keys, as a fraction of the slider's range.
const LOAD_KEY_STEP: f64 = 0.01;

impl AppState {
    /// Carries out `action`. What follows from it that the state does not
    /// own (a lesson step's tab, a recording) comes back, in order, for the
    /// window to apply.
    #[must_use]
    pub fn apply(&mut self, action: Action) -> Vec<Action> {
        match action {
            Action::Command(command) => return self.command(command),
            Action::Preset(id) => self.set_preset(id),
            Action::Enter { key, value } => self.enter_parameter(key, value),
            Action::Refuse { key, why } => self.refuse(key, why),
            Action::ClearRefusal(key) => self.clear_refusal(key),
            Action::Column { preset, model } => self.set_column(preset, model),
            Action::Engine(engine) => self.set_engine(engine),
            Action::Speed(speed) => self.set_speed(speed),
            Action::Projector(on) => self.settings.projector = on,
            Action::Language(language) => {
                self.translate_lesson(self.language, language);
                self.language = language;
                self.language_chosen = true;
            }
            Action::Hold { angles_rad } => self.hold(&angles_rad),
            Action::Release => self.release(),
            Action::KickBy { angle_rad } => self.kick(angle_rad),
            Action::RampStart(ramp) => self.start_ramp(ramp),
            Action::RampPauseResume => self.toggle_ramp_pause(),
            Action::RampStop => self.ramp = None,
            Action::Overlay(id) => self.set_overlay(id),
            Action::MapPick { axis, load, value } => self.set_map_point(&axis, load, value),
            Action::Paste(text) => self.paste_settings(&text),
            Action::LessonOpen(lesson) => return self.open_lesson(*lesson),
            Action::LessonPredict(load) => self.predict_load(load),
            Action::LessonChoose(answer) => self.choose(answer),
            Action::LessonClose => self.lesson = None,
            Action::Say(notice) => self.say(notice),
            Action::DismissNotice => self.notice = None,
            Action::DismissHint => self.first_launch.hint = false,
            Action::CloseWelcome => self.first_launch.welcome = false,
            window @ (Action::Tab(_)
            | Action::Record { .. }
            | Action::SaveCsv(_)
            | Action::SavePicture) => {
                return vec![window];
            }
        }
        Vec::new()
    }

    /// A named button or key.
    fn command(&mut self, command: Command) -> Vec<Action> {
        match command {
            Command::PlayPause => self.running = !self.running,
            Command::Step => self.step(),
            Command::Kick => self.kick(KICK_RAD),
            Command::Reset => self.reset(),
            Command::ResetAll => self.reset_all(),
            Command::LoadUp => self.nudge_load(LOAD_KEY_STEP * self.load_max()),
            Command::LoadDown => self.nudge_load(-LOAD_KEY_STEP * self.load_max()),
            Command::Projector => self.settings.projector = !self.settings.projector,
            Command::LessonNext => return self.lesson_step(true),
            Command::LessonBack => return self.lesson_step(false),
            // The window's, not the state's: `ZieglerApp::apply` takes it.
            Command::FullScreen => {}
        }
        Vec::new()
    }
}
