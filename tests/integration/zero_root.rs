//! The roller always has the root lambda = 0: its spin angle psi appears only
//! through its rate (the third column of K is zero), so psi drifts freely.
//! The analysis removes that root exactly and reports it as a structural
//! branch; here an undeflated 6x6 companion matrix confirms it is a root.

use crate::common;

use common::model;
use nalgebra::DMatrix;
use zieglerlab::analysis::{AffinePencil, locus};
use zieglerlab::model::linearize;

#[test]
fn full_companion_has_a_zero_eigenvalue_at_every_load() {
    for preset in ["roller", "roller-as-printed"] {
        for p in [0.0, 0.01, 1.0, 3.0, 4.3, 8.0] {
            let lin = linearize(&model(preset, &[]).at_load(p)).unwrap();
            assert!(lin.stiffness.column(2).iter().all(|&k| k == 0.0));
            let minv = lin.mass.clone().try_inverse().unwrap();
            let mut a = DMatrix::zeros(6, 6);
            a.view_mut((0, 3), (3, 3))
                .copy_from(&DMatrix::identity(3, 3));
            a.view_mut((3, 0), (3, 3))
                .copy_from(&(-&minv * &lin.stiffness));
            a.view_mut((3, 3), (3, 3))
                .copy_from(&(-&minv * &lin.damping));
            let smallest = a
                .complex_eigenvalues()
                .iter()
                .map(|z| z.norm())
                .fold(f64::INFINITY, f64::min);
            assert!(smallest < 1e-9, "{preset} p={p}: {smallest:e}");
            assert!(a.determinant().abs() < 1e-12);
        }
    }
}

#[test]
fn analysis_reports_the_zero_root_as_a_branch() {
    let pencil = AffinePencil::new(&model("roller", &[])).unwrap();
    let spectrum = pencil.spectrum(2.0).unwrap();
    assert_eq!(spectrum.structural_zeros, 1);
    assert_eq!(spectrum.all().count(), 6);
    assert_eq!(spectrum.all().filter(|z| z.norm() == 0.0).count(), 1);
    let locus = locus(&pencil, 0.0, 6.0, 61).unwrap();
    assert_eq!(locus.branches.len(), 6);
    assert!(locus.branches[5].iter().all(|z| z.norm() == 0.0));
}
