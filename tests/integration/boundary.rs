//! The stability boundaries followed in a second parameter agree with the
//! critical loads found one value at a time: every point of a boundary is
//! a critical load `critical` finds there; a Bautin point is where the
//! first Lyapunov coefficient of `critical --json` changes sign (bisected
//! here through the command line); a Bogdanov-Takens point has two
//! eigenvalues at zero; the dead load's divergence loads are Ziegler's
//! closed form; the curves' rows reach the range's ends exactly.

use crate::cli::run;
use crate::common::{model, transitions};
use zieglerlab::analysis::{
    AffinePencil, BoundaryKind, BoundarySpec, SpecialKind, State, boundaries,
};
use zieglerlab::model::{Axis, Model};

/// The boundaries of `name` with `sets` over `key` in `range`, loads 0 to 8.
fn boundaries_of(
    name: &str,
    sets: &[&str],
    key: &str,
    range: (f64, f64),
) -> (Model, Axis, zieglerlab::analysis::Boundaries) {
    let m = model(name, sets);
    let axis = Axis::parse(key, &m).unwrap();
    let spec = BoundarySpec {
        model: m,
        axis: axis.clone(),
        axis_range: range,
        load_range: (0.0, 8.0),
    };
    (m, axis.clone(), boundaries(&spec).expect("boundaries"))
}

/// The first Lyapunov coefficient at the first flutter onset that
/// `critical --json` reports for `sets`.
fn critical_l1(sets: &[String]) -> f64 {
    let mut args = vec!["critical", "--preset", "ziegler-1952", "--json"];
    for set in sets {
        args.extend(["--set", set.as_str()]);
    }
    let out = run(&args);
    assert!(out.status.success(), "{out:?}");
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    json["transitions"][0]["hopf"]["first_lyapunov"]
        .as_f64()
        .expect("a first Lyapunov coefficient")
}

/// Drag along the rods with a light first rod turns the onset hard
/// (the README's hard example); the default first rod's is soft. Between
/// them lies a Bautin point. Bisecting the sign of `critical --json`'s
/// first Lyapunov coefficient in m1 finds it where the boundary does, and
/// every point of the Hopf curve is the flutter onset `critical` finds at
/// its m1.
#[test]
fn a_bautin_point_is_where_the_first_lyapunov_coefficient_changes_sign() {
    let (m, axis, found) = boundaries_of("ziegler-1952", &["c_ext=0.05"], "m1", (0.2, 2.0));
    let flutter: Vec<_> = found
        .curves
        .iter()
        .filter(|c| c.kind == BoundaryKind::Flutter)
        .collect();
    assert_eq!(flutter.len(), 1, "{found:?}");
    let curve = flutter[0];
    // The rows reach both ends of m1's range exactly.
    let ends = [
        curve.points[0].value,
        curve.points[curve.points.len() - 1].value,
    ];
    assert!(ends.contains(&0.2) && ends.contains(&2.0), "{ends:?}");
    for point in curve.points.iter().step_by(5) {
        let at = axis.apply(&m, point.value).unwrap();
        let onset = transitions(&at, 8.0)
            .into_iter()
            .find(|t| t.from == State::Stable && t.to == State::Flutter)
            .expect("a flutter onset");
        assert!(
            (onset.load - point.load).abs() <= 1e-8 * onset.load,
            "m1 = {}: {} against {}",
            point.value,
            point.load,
            onset.load
        );
    }
    let bautin: Vec<_> = found
        .special_points
        .iter()
        .filter(|s| s.kind == SpecialKind::Bautin)
        .collect();
    assert_eq!(bautin.len(), 1, "{:?}", found.special_points);
    let sets = |m1: f64| vec!["c_ext=0.05".to_owned(), format!("m1={m1:.17e}")];
    let (mut hard, mut soft) = (0.2, 2.0);
    assert!(critical_l1(&sets(hard)) > 0.0 && critical_l1(&sets(soft)) < 0.0);
    while soft - hard > 1e-7 {
        let middle = 0.5 * (hard + soft);
        if critical_l1(&sets(middle)) > 0.0 {
            hard = middle;
        } else {
            soft = middle;
        }
    }
    let point = bautin[0];
    assert!(
        (point.value - 0.5 * (hard + soft)).abs() < 1e-6,
        "Bautin at m1 = {}, critical's sign change at {hard} to {soft}",
        point.value
    );
    let at = axis.apply(&m, point.value).unwrap();
    let onset = transitions(&at, 8.0)[0].load;
    assert!(
        (onset - point.load).abs() < 1e-8,
        "{onset} against {}",
        point.load
    );
    // Soft on the heavy side, hard on the light side.
    for p in &curve.points {
        let l1 = p.first_lyapunov.expect("a damped column's coefficient");
        assert_eq!(l1 > 0.0, p.value < point.value, "m1 = {}: {l1}", p.value);
    }
}

/// The partial follower (tangency eta) with equal dampers: under a dead
/// load (eta = 0) the column diverges at Ziegler's p = (3 -+ sqrt 5)/2, and
/// the divergence curve from those two loads folds back in eta, followed
/// round its fold; the flutter curve from eta = 1 ends on it where its
/// frequency falls to zero, a Bogdanov-Takens point with two eigenvalues
/// at zero, on the divergence curve's fold (eta = 5/9, p = 3/2).
#[test]
fn the_hopf_curve_ends_where_the_divergence_curve_holds_a_double_zero() {
    let (m, axis, found) = boundaries_of("ziegler-1952", &["c1=0.1", "c2=0.1"], "eta", (0.0, 1.0));
    let divergence: Vec<_> = found
        .curves
        .iter()
        .filter(|c| c.kind == BoundaryKind::Divergence)
        .collect();
    assert_eq!(divergence.len(), 1, "one curve, through its fold");
    let curve = &divergence[0].points;
    let (first, last) = (curve[0], curve[curve.len() - 1]);
    assert_eq!((first.value, last.value), (0.0, 0.0));
    let mut loads = [first.load, last.load];
    loads.sort_by(f64::total_cmp);
    let closed = [0.5 * (3.0 - 5f64.sqrt()), 0.5 * (3.0 + 5f64.sqrt())];
    for (load, exact) in loads.iter().zip(closed) {
        assert!((load - exact).abs() < 1e-10, "{load} against {exact}");
    }
    let furthest = curve.iter().map(|p| p.value).fold(0.0, f64::max);
    assert!(furthest > 0.5, "the fold at eta = {furthest}");
    let bt: Vec<_> = found
        .special_points
        .iter()
        .filter(|s| s.kind == SpecialKind::BogdanovTakens)
        .collect();
    assert_eq!(bt.len(), 1, "{:?}", found.special_points);
    // With joint dampers in proportion to the joint springs, u C v of the
    // null vectors of K is p u G v (G the load's part of K), so the double
    // zero is where det K = 1 - 3(1 - eta) p + (1 - eta) p^2 = 0 turns
    // back in eta: p = 3/2, eta = 5/9.
    assert!(
        (bt[0].value - 5.0 / 9.0).abs() < 1e-5 && (bt[0].load - 1.5).abs() < 1e-5,
        "{:?}",
        bt[0]
    );
    let at = axis.apply(&m, bt[0].value).unwrap();
    let spectrum = AffinePencil::new(&at)
        .unwrap()
        .spectrum(bt[0].load)
        .unwrap();
    let mut sizes: Vec<f64> = spectrum.eigenvalues.iter().map(|z| z.norm()).collect();
    sizes.sort_by(f64::total_cmp);
    assert!(
        sizes[1] < 1e-2 * spectrum.scale_per_s,
        "two eigenvalues near zero: {sizes:?}"
    );
    assert!(sizes[2] > 0.1 * spectrum.scale_per_s, "{sizes:?}");
}

/// The command line: the CSV's header names the key as typed, flutter
/// rows say soft or hard by the coefficient's sign, divergence rows say
/// nothing; a second parameter that is the load is refused.
#[test]
fn boundary_writes_its_curves_as_csv() {
    let out = run(&[
        "boundary",
        "--preset",
        "ziegler-1952",
        "--set",
        "c1=0.1",
        "--set",
        "c2=0.1",
        "--y",
        "eta:0:1",
    ]);
    assert!(out.status.success(), "{out:?}");
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("curve,eta,load,first_lyapunov,onset"));
    let mut kinds = std::collections::BTreeSet::new();
    for line in lines {
        let fields: Vec<&str> = line.split(',').collect();
        assert_eq!(fields.len(), 5, "{line}");
        let kind = fields[0].split('-').next().unwrap();
        kinds.insert(kind.to_owned());
        match kind {
            "flutter" => {
                let l1: f64 = fields[3].parse().unwrap();
                assert_eq!(fields[4], if l1 < 0.0 { "soft" } else { "hard" }, "{line}");
            }
            "divergence" => assert_eq!((fields[3], fields[4]), ("", ""), "{line}"),
            other => panic!("{other}"),
        }
    }
    assert_eq!(kinds.len(), 2, "{kinds:?}");
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(said.contains("bogdanov-takens: eta = 0.555"), "{said}");
    for y in ["load:0:1", "rods:2:8"] {
        let refused = run(&["boundary", "--preset", "ziegler-1952", "--y", y]);
        assert_eq!(refused.status.code(), Some(2), "{y}");
    }
}

/// The README's example of `boundary` is what the command prints: the
/// Bautin line on stderr, then the CSV's first two lines.
#[test]
fn the_readme_example_of_boundary_is_what_it_prints() {
    let readme = std::fs::read_to_string("README.md").expect("the README");
    let command =
        "    $ zieglerlab boundary --preset ziegler-1952 --set c_ext=0.05 --y m1:0.2:2 | head -3\n";
    let start = readme.find(command).expect("the example") + command.len();
    let shown: Vec<&str> = readme[start..]
        .lines()
        .take_while(|line| line.starts_with("    ") && !line.trim_start().starts_with('$'))
        .map(|line| &line[4..])
        .collect();
    let out = run(&[
        "boundary",
        "--preset",
        "ziegler-1952",
        "--set",
        "c_ext=0.05",
        "--y",
        "m1:0.2:2",
    ]);
    assert!(out.status.success(), "{out:?}");
    let said = String::from_utf8(out.stderr).unwrap();
    let printed = String::from_utf8(out.stdout).unwrap();
    let mut made: Vec<&str> = said.lines().collect();
    made.extend(printed.lines().take(2));
    assert_eq!(shown, made);
}
