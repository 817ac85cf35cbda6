//! Eigenvalues measured from a run: the matrix pencil method (Hua and Sarkar,
//! 1990) on the sampled angles, so a plot can put "measured" next to
//! "predicted".

use nalgebra::{Complex, DMatrix, linalg::Schur};

/// Eigenvalues (1/s) of the damped exponentials that make up `channels`,
/// all sampled every `dt_secs` over the same window. `order` is how many
/// exponentials to fit (each oscillating mode counts two). Sorted by
/// decreasing real part. `None` when the window is too short for the order
/// or the decomposition fails.
///
/// The channels' Hankel matrices are stacked, so every channel shares the
/// poles; a truncated SVD to `order` singular vectors filters the rest.
#[must_use]
pub fn identify(channels: &[&[f64]], dt_secs: f64, order: usize) -> Option<Vec<Complex<f64>>> {
    let n = channels.first()?.len();
    if channels.iter().any(|c| c.len() != n) || order == 0 || !dt_secs.is_finite() || dt_secs <= 0.0
    {
        return None;
    }
    // Pencil parameter between n/3 and n/2 is the method's sweet spot.
    let pencil = n / 3;
    let rows_per_channel = n - pencil;
    if pencil <= order || rows_per_channel <= order {
        return None;
    }
    let mut hankel = DMatrix::zeros(rows_per_channel * channels.len(), pencil + 1);
    for (c, channel) in channels.iter().enumerate() {
        if channel.iter().any(|v| !v.is_finite()) {
            return None;
        }
        for i in 0..rows_per_channel {
            for j in 0..=pencil {
                hankel[(c * rows_per_channel + i, j)] = channel[i + j];
            }
        }
    }
    let svd = hankel.svd(false, true);
    let v_t = svd.v_t?;
    // The signal subspace: the `order` dominant right singular vectors
    // (nalgebra sorts singular values in decreasing order).
    let v = v_t.rows(0, order).transpose();
    let v1 = v.rows(0, pencil).into_owned();
    let v2 = v.rows(1, pencil).into_owned();
    let shift = v1.pseudo_inverse(1e-14).ok()? * v2;
    let mut eigenvalues: Vec<Complex<f64>> = Schur::try_new(shift, f64::EPSILON, 10_000)?
        .complex_eigenvalues()
        .iter()
        .map(|z| z.ln() / dt_secs)
        .collect();
    if eigenvalues
        .iter()
        .any(|z| !(z.re.is_finite() && z.im.is_finite()))
    {
        return None;
    }
    eigenvalues.sort_by(|a, b| b.re.total_cmp(&a.re));
    Some(eigenvalues)
}
