//! Helpers shared by the tests: building models, reading spectra, and
//! running the binary and other programs under a time limit (a test fails,
//! it never hangs).

#![allow(dead_code, reason = "each test module uses a different subset")]
use zieglerlab::analysis::{AffinePencil, C64, Transition, critical_loads, cycle_branches};
use zieglerlab::model::{
    Model, StateVec, apply_assignments, energy_j, parse_assignment, preset, state_derivative,
};
use zieglerlab::sim::{EngineKind, Simulation, identify, initial_state};

/// The preset `name` with `key=value` overrides.
pub fn model(name: &str, sets: &[&str]) -> Model {
    let preset = preset(name).unwrap();
    let mut model = preset.model();
    let assignments: Vec<_> = sets.iter().map(|s| parse_assignment(s).unwrap()).collect();
    apply_assignments(&mut model, &assignments).unwrap();
    model
}

/// The affine pencil of the preset `name` with overrides.
pub fn pencil(name: &str, sets: &[&str]) -> AffinePencil {
    AffinePencil::new(&model(name, sets)).unwrap()
}

/// Every stability change of `model` for p in `[0, load_max]`.
pub fn transitions(model: &Model, load_max: f64) -> Vec<Transition> {
    critical_loads(&AffinePencil::new(model).unwrap(), 0.0, load_max).unwrap()
}

/// The moving eigenvalues of `model` at its own load (Schur path).
pub fn eigenvalues(model: &Model) -> Vec<C64> {
    AffinePencil::new(model)
        .unwrap()
        .spectrum(model.load_p())
        .unwrap()
        .eigenvalues
}

/// Largest distance from each of `a` to the nearest of `b`, and back.
pub fn set_distance(a: &[C64], b: &[C64]) -> f64 {
    let one_way = |x: &[C64], y: &[C64]| {
        x.iter()
            .map(|p| {
                y.iter()
                    .map(|q| (p - q).norm())
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0, f64::max)
    };
    one_way(a, b).max(one_way(b, a))
}

/// Asserts `actual` is within `relative` of `expected`.
#[track_caller]
pub fn assert_close(actual: f64, expected: f64, relative: f64) {
    let error = (actual - expected).abs() / expected.abs();
    assert!(
        error <= relative,
        "{actual} vs {expected}: relative error {error:e} > {relative:e}"
    );
}

/// Runs `model` from the standard 1e-3 rad kick for `duration_secs` and
/// identifies `order` eigenvalues from about 600 samples of phi1 and phi2.
pub fn identified(
    model: &Model,
    engine: EngineKind,
    step_secs: f64,
    duration_secs: f64,
    order: usize,
) -> Vec<C64> {
    let mut sim = Simulation::new(*model, engine, initial_state(model, 1e-3), step_secs).unwrap();
    let (mut phi1, mut phi2) = (vec![sim.observe().phi1_rad], vec![sim.observe().phi2_rad]);
    let every = ((duration_secs / step_secs) / 600.0).ceil().max(1.0);
    let mut count = 0.0;
    sim.run(duration_secs, |o| {
        count += 1.0;
        if count % every == 0.0 {
            phi1.push(o.phi1_rad);
            phi2.push(o.phi2_rad);
        }
    });
    identify(&[&phi1, &phi2], every * step_secs, order).unwrap()
}

/// The predicted eigenvalues of `model` at its load, without the structural
/// zeros and without real eigenvalues faster than `fastest_per_s` (the
/// roller's spin relaxation, gone before the first samples).
pub fn predicted(model: &Model, fastest_per_s: f64) -> Vec<C64> {
    eigenvalues(model)
        .into_iter()
        .filter(|z| z.im != 0.0 || z.re.abs() < fastest_per_s)
        .collect()
}

/// A few large-amplitude states (angles up to about a radian, fast rates).
pub fn states() -> Vec<StateVec> {
    vec![
        StateVec::from_row_slice(&[0.4, -0.9, 0.3, 1.1, -0.7, 2.0]),
        StateVec::from_row_slice(&[-1.2, 0.5, -2.0, -0.3, 1.9, -0.5]),
        StateVec::from_row_slice(&[0.05, 0.8, 0.0, 0.02, -0.01, 0.4]),
    ]
}

/// dE/dt along the flow by central differences of the energy.
pub fn energy_rate(model: &Model, x: &StateVec, potential: impl Fn(&StateVec) -> f64) -> f64 {
    let f = state_derivative(model, x);
    let h = 1e-6;
    let energy = |y: &StateVec| {
        let (kinetic, spring) = energy_j(model, y);
        kinetic + spring + potential(y)
    };
    (energy(&(x + h * &f)) - energy(&(x - h * &f))) / (2.0 * h)
}

/// `int_0^length f(s) ds` by Simpson's rule on 200 intervals.
pub fn simpson(f: impl Fn(f64) -> f64, length: f64) -> f64 {
    let n = 200;
    let h = length / f64::from(n);
    let weight = |i: u32| match i {
        0 | 200 => 1.0,
        _ if i % 2 == 1 => 4.0,
        _ => 2.0,
    };
    (0..=n)
        .map(|i| weight(i) * f(h * f64::from(i)))
        .sum::<f64>()
        * h
        / 3.0
}

/// Enters `value` for `key` in the app as a field or the load bar does,
/// and checks it was taken.
pub fn enter(app: &mut zieglerlab::app::ZieglerApp, key: zieglerlab::model::Key, value: f64) {
    app.apply(zieglerlab::app::Action::Enter { key, value });
    assert_eq!(app.state().refusal(key), None, "{key} = {value}");
}

/// The message line's text in `app` ("" when it says nothing).
pub fn message_line(app: &zieglerlab::app::ZieglerApp) -> String {
    app.state()
        .notice()
        .map(|n| n.text.clone())
        .unwrap_or_default()
}

/// Waits for `child` to end; after `limit` it is killed and the test fails,
/// saying `why` (so a hang fails instead of freezing CI).
pub fn wait_within(
    child: &mut std::process::Child,
    limit: std::time::Duration,
    why: &str,
) -> std::process::ExitStatus {
    let start = std::time::Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            return status;
        }
        if start.elapsed() > limit {
            child.kill().unwrap();
            panic!("{why} after {limit:?}");
        }
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
}

/// What `command` writes and its status, as `Command::output` gives them,
/// but within `limit`: past it the program is killed and the test fails
/// naming `what`. `expect` says what to install when the program is missing.
pub fn output_within(
    command: &mut std::process::Command,
    limit: std::time::Duration,
    what: &str,
    expect: &str,
) -> std::process::Output {
    use std::io::Read as _;
    use std::process::Stdio;
    let mut child = command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect(expect);
    // Readers on their own threads, so a full pipe cannot stall the child.
    let mut stdout = child.stdout.take().unwrap();
    let mut stderr = child.stderr.take().unwrap();
    let out_reader = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        stdout.read_to_end(&mut bytes).map(|_| bytes)
    });
    let err_reader = std::thread::spawn(move || {
        let mut bytes = Vec::new();
        stderr.read_to_end(&mut bytes).map(|_| bytes)
    });
    let status = wait_within(&mut child, limit, &format!("{what}: no answer"));
    std::process::Output {
        status,
        stdout: out_reader.join().unwrap().unwrap(),
        stderr: err_reader.join().unwrap().unwrap(),
    }
}

/// The analysis of `model` (named `name`) from load 0 to `load_max`, as a
/// figure gathers it.
pub fn analysed_to(
    name: &str,
    model: &Model,
    load_max: f64,
) -> Result<zieglerlab::plot::locus::Analysed, zieglerlab::analysis::AnalysisError> {
    zieglerlab::plot::locus::Analysed::new(name, model, (0.0, load_max), 2)
}

/// A figure's sheet of the locus `part` of `main` with `overlays` behind,
/// in English.
pub fn paper_loci(
    main: &zieglerlab::plot::locus::Analysed,
    overlays: &[zieglerlab::plot::locus::Analysed],
    part: zieglerlab::plot::locus::Part,
) -> zieglerlab::plot::spec::Sheet {
    zieglerlab::plot::locus::Loci {
        main: main.layer(),
        others: overlays
            .iter()
            .map(zieglerlab::plot::locus::Analysed::layer)
            .collect(),
        medium: zieglerlab::plot::spec::Medium::Paper,
        words: zieglerlab::i18n::words(zieglerlab::i18n::Language::English),
    }
    .sheet(part)
}

/// The drag column (`c_ext = 0.05`) of the README's `boundary` example,
/// its second parameter m1 over 0.2 to 2 with loads 0 to 8, and its
/// boundaries: computed once (a few seconds: the fold of cycles) for every
/// test that reads them.
pub fn drag_column_boundaries() -> &'static (
    zieglerlab::analysis::BoundarySpec,
    zieglerlab::analysis::Boundaries,
) {
    static FOUND: std::sync::OnceLock<(
        zieglerlab::analysis::BoundarySpec,
        zieglerlab::analysis::Boundaries,
    )> = std::sync::OnceLock::new();
    FOUND.get_or_init(|| {
        let m = model("ziegler-1952", &["c_ext=0.05"]);
        let spec = zieglerlab::analysis::BoundarySpec {
            model: m,
            axis: zieglerlab::model::Axis::parse("m1", &m).unwrap(),
            axis_range: (0.2, 2.0),
            load_range: (0.0, 8.0),
        };
        let found = zieglerlab::analysis::boundaries(&spec).expect("boundaries");
        (spec, found)
    })
}

/// The largest `|phi_i|` of a two-rod column over two periods after 60
/// periods of a run from `x0` on `engine` (steps of 1/240 s).
pub fn settled(m: &Model, engine: EngineKind, x0: nalgebra::DVector<f64>, period: f64) -> Vec<f64> {
    let mut sim = Simulation::new(*m, engine, x0, 1.0 / 240.0).expect("a run");
    sim.run(60.0 * period, |_| ());
    let mut largest = vec![0.0_f64; 2];
    sim.run(2.0 * period, |o| {
        for (most, angle) in largest.iter_mut().zip(&o.angles_rad) {
            *most = most.max(angle.abs());
        }
    });
    largest
}

/// The branch of cycles of the hard onset (Ziegler's column with drag
/// `c_ext = 0.05` and a light first rod, `m1 = 0.2`) over the window's
/// loads, 0 to 8, computed once.
pub fn hard_onset_branch() -> &'static (zieglerlab::model::Model, zieglerlab::analysis::Branch) {
    static BRANCH: std::sync::OnceLock<(zieglerlab::model::Model, zieglerlab::analysis::Branch)> =
        std::sync::OnceLock::new();
    BRANCH.get_or_init(|| {
        let m = model("ziegler-1952", &["c_ext=0.05", "m1=0.2"]);
        let never = std::sync::atomic::AtomicBool::new(false);
        let onset = cycle_branches(&m, 0.0, 8.0, &never).unwrap().remove(0);
        (m, onset.branch.expect("a branch"))
    })
}

/// The half-period map `R = -D Phi(T/2)` of `cycle` on the angles and
/// rates, and `|x(T/2) + x(0)|` (zero for a cycle that is its own mirror
/// image half a period on), by [`flow_derivative`].
pub fn half_period_map(
    m: &zieglerlab::model::Model,
    cycle: &zieglerlab::analysis::Cycle,
) -> (nalgebra::DMatrix<f64>, f64) {
    let (derivative, end) = flow_derivative(m, cycle, cycle.period_secs / 2.0);
    let at = m.at_load(cycle.load);
    (-derivative, (end + cycle.start_state(&at)).amax())
}

/// The derivative `D Phi(secs)` of the flow from `cycle`'s start at its
/// load on the two rods' angles and rates, and the flow's end, by a plain
/// fourth-order Runge-Kutta run of the equations of motion
/// (`state_derivative`, 8000 steps a period) and central differences:
/// independent of the shooting's Gauss-Legendre steps and their exact
/// derivative.
pub fn flow_derivative(
    m: &zieglerlab::model::Model,
    cycle: &zieglerlab::analysis::Cycle,
    secs: f64,
) -> (nalgebra::DMatrix<f64>, nalgebra::DVector<f64>) {
    let at = m.at_load(cycle.load);
    #[expect(
        clippy::cast_possible_truncation,
        clippy::cast_sign_loss,
        reason = "a few thousand steps"
    )]
    let steps = (8000.0 * secs / cycle.period_secs).ceil() as u32;
    let run = |x: nalgebra::DVector<f64>| rk4(&at, x, secs, steps);
    let x0 = cycle.start_state(&at);
    // The angles and rates of the two rods (the spin entries stay zero).
    let moving = [0, 1, 3, 4];
    let step = 1e-6;
    let mut map = nalgebra::DMatrix::zeros(4, 4);
    for (column, &k) in moving.iter().enumerate() {
        let (mut plus, mut minus) = (x0.clone(), x0.clone());
        plus[k] += step;
        minus[k] -= step;
        let derivative = (run(plus) - run(minus)) / (2.0 * step);
        for (row, &r) in moving.iter().enumerate() {
            map[(row, column)] = derivative[r];
        }
    }
    (map, run(x0))
}

/// What a screen reader hears of the bifurcation diagram of `branch` over
/// the window's loads (0 to 8), in English, and the diagram's legend.
pub fn diagram_said(branch: &zieglerlab::analysis::Branch) -> (String, Vec<String>) {
    let words = zieglerlab::i18n::words(zieglerlab::i18n::Language::English);
    let sheet = zieglerlab::plot::bifurcation::Diagram {
        load_range: (0.0, 8.0),
        equilibrium: &[],
        branches: vec![branch],
        sweep: &[],
        present: None,
        words,
    }
    .sheet();
    let legend = sheet.legend.iter().map(|e| e.text.clone()).collect();
    (
        zieglerlab::plot::describe::describe(&sheet.plots[0], words),
        legend,
    )
}

/// `x` after `secs` of a plain fourth-order Runge-Kutta run of the
/// equations of motion of `at` in `steps` steps (independent of the
/// shooting's Gauss-Legendre steps).
pub fn rk4(
    at: &Model,
    mut x: nalgebra::DVector<f64>,
    secs: f64,
    steps: u32,
) -> nalgebra::DVector<f64> {
    let h = secs / f64::from(steps);
    for _ in 0..steps {
        let k1 = state_derivative(at, &x);
        let k2 = state_derivative(at, &(&x + &k1 * (h / 2.0)));
        let k3 = state_derivative(at, &(&x + &k2 * (h / 2.0)));
        let k4 = state_derivative(at, &(&x + &k3 * h));
        x += (k1 + k2 * 2.0 + k3 * 2.0 + k4) * (h / 6.0);
    }
    x
}
