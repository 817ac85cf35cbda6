//! Eigenvalues measured from a run: the matrix pencil method (Hua and Sarkar,
//! 1990) on the sampled angles, so a plot can put "measured" next to
//! "predicted".

use faer::linalg::solvers::SolveLstsq;
use nalgebra::Complex;

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
    let mut hankel = faer::Mat::<f64>::zeros(rows_per_channel * channels.len(), pencil + 1);
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
    // By faer: nalgebra's SVD of this matrix (1190 x 199 for a 4-rod
    // chain's run) gave right singular vectors that put a growing pair of
    // modes at +-0.49 1/s on the real axis, where numpy's and faer's SVD of
    // the same samples give the predicted pair to 1e-5.
    let svd = hankel.thin_svd().ok()?;
    // The signal subspace: the `order` dominant right singular vectors
    // (sorted by decreasing singular value), and the shift between its
    // rows, by least squares.
    let v = svd.V().subcols(0, order);
    let (v1, v2) = (v.subrows(0, pencil), v.subrows(1, pencil));
    let shift = v1.qr().solve_lstsq(v2);
    let mut eigenvalues: Vec<Complex<f64>> = shift
        .eigenvalues()
        .ok()?
        .iter()
        .map(|z| Complex::new(z.re, z.im).ln() / dt_secs)
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

#[cfg(test)]
mod tests {
    use super::*;

    /// Two channels made of the eigenvalues of a 4-rod chain past its
    /// flutter onset (a growing pair, its decaying twin at the same
    /// frequency, two undamped pairs), sampled as the tests sample a run:
    /// each eigenvalue comes back to 1e-7 of the largest.
    #[test]
    fn a_sum_of_known_modes_is_taken_apart() {
        let modes = [
            Complex::new(0.066_44, 0.160_29),
            Complex::new(-0.066_44, 0.160_29),
            Complex::new(0.0, 1.531_59),
            Complex::new(0.0, 0.792_70),
        ];
        let (dt_secs, samples) = (0.058_333, 595);
        let channel = |weights: [(f64, f64); 4]| -> Vec<f64> {
            (0..samples)
                .map(|i| {
                    let t = f64::from(i) * dt_secs;
                    modes
                        .iter()
                        .zip(weights)
                        .map(|(z, (amplitude, phase))| {
                            amplitude * (z.re * t).exp() * (z.im * t + phase).cos()
                        })
                        .sum()
                })
                .collect()
        };
        let first = channel([(3e-4, 0.3), (4e-4, -1.1), (2e-4, 0.7), (1e-4, 2.0)]);
        let second = channel([(7e-4, -0.4), (1e-4, 0.9), (5e-4, 1.6), (3e-4, -2.2)]);
        let found = identify(&[&first, &second], dt_secs, 8).expect("identified");
        assert_eq!(found.len(), 8);
        let scale = 1.531_59;
        for z in modes.iter().flat_map(|z| [*z, z.conj()]) {
            let off = found
                .iter()
                .map(|f| (f - z).norm())
                .fold(f64::INFINITY, f64::min);
            assert!(off < 1e-7 * scale, "{z}: {off}, found {found:?}");
        }
    }
}
