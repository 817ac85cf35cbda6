//! numpy's times for the same work as two of the figures, taken in a
//! python3 child process: the batched eigenvalues of the locus's companion
//! matrices, and a plain scan for a long chain's first flutter load.

use anyhow::Result;
use nalgebra::DMatrix;

use super::{Chain, LOCUS_LOADS};
use crate::analysis::{AffinePencil, critical_loads, first_loss_of_stability, load_grid};

/// Times numpy's batched `eigvals` in a python3 child process on the first-order
/// companion matrices `[[0, I], [-M^-1 K, -M^-1 D]]` of `pencil` at the
/// benchmarked locus's loads. `None` when python3 or numpy is missing.
pub(super) fn numpy_eig_us_per_pencil(pencil: &AffinePencil) -> Result<Option<f64>> {
    const SCRIPT: &str = r"
a = np.array(json.load(sys.stdin))
np.linalg.eigvals(a)
times = []
for _ in range(31):
    start = time.perf_counter(); np.linalg.eigvals(a); times.append(time.perf_counter() - start)
times.sort()
print(times[len(times) // 2] * 1e6 / len(a))
";
    let mut matrices = Vec::with_capacity(LOCUS_LOADS);
    for p in load_grid(0.0, pencil.natural_load_max(), LOCUS_LOADS)? {
        let lin = pencil.at(p);
        let n = lin.mass.nrows();
        let Some(mass_inv) = lin.mass.clone().try_inverse() else {
            anyhow::bail!("a singular mass matrix at p = {p}");
        };
        let mut a = DMatrix::<f64>::zeros(2 * n, 2 * n);
        a.view_mut((0, n), (n, n)).fill_with_identity();
        a.view_mut((n, 0), (n, n))
            .copy_from(&(-&mass_inv * &lin.stiffness));
        a.view_mut((n, n), (n, n))
            .copy_from(&(-&mass_inv * &lin.damping));
        matrices.push(rows(&a));
    }
    let Some(text) = run_numpy(SCRIPT, &serde_json::to_vec(&matrices)?)? else {
        return Ok(None);
    };
    Ok(text.trim().parse::<f64>().ok().filter(|us| us.is_finite()))
}

/// The rows of `a`, for JSON.
fn rows(a: &DMatrix<f64>) -> Vec<Vec<f64>> {
    a.row_iter().map(|r| r.iter().copied().collect()).collect()
}

/// Times, in a python3 child process, the plain numpy scan for the first
/// flutter load of the undamped `chain`: the eigenvalues `mu` of `M^-1 K(p)`
/// at 400 loads over the analysis range in one batched call (stable while
/// every `mu` is real and positive), then 50 bisection steps in the first
/// bracket that loses stability. `None` without python3 or numpy; an error
/// when the load it finds is not [`critical_loads`]' first loss.
pub(super) fn numpy_chain_scan_ms(chain: &Chain) -> Result<Option<f64>> {
    const SCRIPT: &str = r"
d = json.load(sys.stdin)
m, k0, k1 = (np.array(d[k]) for k in ('mass', 'stiffness', 'per_load'))
p_max = d['load_max']
def unstable(mu):
    tol = 1e-9 * np.abs(mu).max(axis=-1, keepdims=True)
    return ((np.abs(mu.imag) > tol) | (mu.real < -tol)).any(axis=-1)
def scan():
    loads = np.linspace(0.0, p_max, 400)
    mu = np.linalg.eigvals(np.linalg.solve(m, k0 + loads[:, None, None] * k1))
    lost = unstable(mu)
    i = int(np.argmax(lost))
    if not lost[i] or i == 0:
        return float('nan')
    a, b = loads[i - 1], loads[i]
    for _ in range(50):
        c = 0.5 * (a + b)
        if unstable(np.linalg.eigvals(np.linalg.solve(m, k0 + c * k1))):
            b = c
        else:
            a = c
    return b
scan()
times = []
for _ in range(7):
    start = time.perf_counter(); load = scan(); times.append(time.perf_counter() - start)
times.sort()
print(times[len(times) // 2] * 1e3, load)
";
    let lin = chain.pencil.at(0.0);
    let per_load = &chain.pencil.at(1.0).stiffness - &lin.stiffness;
    let input = serde_json::json!({
        "mass": rows(&lin.mass),
        "stiffness": rows(&lin.stiffness),
        "per_load": rows(&per_load),
        "load_max": chain.load_max,
    });
    let Some(text) = run_numpy(SCRIPT, &serde_json::to_vec(&input)?)? else {
        return Ok(None);
    };
    let mut words = text.split_whitespace().map(str::parse::<f64>);
    let (Some(Ok(ms)), Some(Ok(load))) = (words.next(), words.next()) else {
        return Ok(None);
    };
    let first_loss = first_loss_of_stability(&critical_loads(&chain.pencil, 0.0, chain.load_max)?);
    match first_loss {
        Some(ours) if (ours - load).abs() <= 1e-6 * ours => Ok(Some(ms)),
        _ => anyhow::bail!("numpy's scan finds p = {load}, critical {first_loss:?}"),
    }
}

/// Runs `script` in a python3 child process (with `json`, `sys`, `time`
/// and numpy as `np` imported) with `input` on its stdin: its output, or
/// `None` when python3 or numpy is missing.
fn run_numpy(script: &str, input: &[u8]) -> Result<Option<String>> {
    let script = format!(
        "import json, sys, time\ntry:\n    import numpy as np\nexcept ImportError:\n    sys.exit(3)\n{script}"
    );
    let child = std::process::Command::new("python3")
        .args(["-c", &script])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn();
    let Ok(mut child) = child else {
        return Ok(None);
    };
    if let Some(mut stdin) = child.stdin.take() {
        use std::io::Write as _;
        // A child that exits early (no numpy) closes the pipe: not an error here.
        drop(stdin.write_all(input));
    }
    let output = child.wait_with_output()?;
    Ok(output
        .status
        .success()
        .then(|| String::from_utf8_lossy(&output.stdout).into_owned()))
}
