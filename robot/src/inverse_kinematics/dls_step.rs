//! The damped least-squares step: `dq = J'ᵀ (J' J'ᵀ + λ² I)⁻¹ e`, with `J'` the Jacobian
//! restricted to the directions the tolerances constrain. A 6×6 Cholesky solve, no
//! allocation.

use glam::{DMat3, DVec3};

use crate::inverse_kinematics::position_tolerance::{Residual, outer};

/// Writes into `dq` the damped least-squares step that moves the frame by the corrections of
/// `position` and `orientation`, given the Jacobian `columns` (linear, angular per
/// coordinate) and the damping `lambda2 = λ²` (> 0, which keeps the system positive
/// definite whatever the Jacobian's rank).
pub(crate) fn dls_step(
    columns: &[(DVec3, DVec3)],
    position: &Residual,
    orientation: &Residual,
    lambda2: f64,
    dq: &mut [f64],
) {
    // J Jᵀ by blocks.
    let (mut ll, mut lr, mut rr) = (DMat3::ZERO, DMat3::ZERO, DMat3::ZERO);
    for &(a, b) in columns {
        ll += outer(a, a);
        lr += outer(a, b);
        rr += outer(b, b);
    }
    let (pl, pr) = (&position.projector, &orientation.projector);
    let ll = *pl * ll * *pl + DMat3::from_diagonal(DVec3::splat(lambda2));
    let lr = *pl * lr * *pr;
    let rr = *pr * rr * *pr + DMat3::from_diagonal(DVec3::splat(lambda2));
    let mut a = [[0.0; 6]; 6];
    for i in 0..3 {
        for j in 0..3 {
            a[i][j] = ll.col(j)[i];
            a[i][j + 3] = lr.col(j)[i];
            a[j + 3][i] = lr.col(j)[i];
            a[i + 3][j + 3] = rr.col(j)[i];
        }
    }
    let (el, er) = (position.correction, orientation.correction);
    let mut y = [el.x, el.y, el.z, er.x, er.y, er.z];
    cholesky_solve(&mut a, &mut y);
    let yl = *pl * DVec3::new(y[0], y[1], y[2]);
    let yr = *pr * DVec3::new(y[3], y[4], y[5]);
    for (d, &(a, b)) in dq.iter_mut().zip(columns) {
        *d = a.dot(yl) + b.dot(yr);
    }
}

/// Solves `a x = b` in place (`b` becomes `x`) for a symmetric positive definite `a`
/// (overwritten by its Cholesky factor). A non-positive pivot, which rounding could only
/// cause for a damping far below the Jacobian's scale, is floored at a tiny positive value.
fn cholesky_solve(a: &mut [[f64; 6]; 6], b: &mut [f64; 6]) {
    for j in 0..6 {
        let d = (a[j][j] - dot(&a[j][..j], &a[j][..j])).max(1e-300).sqrt();
        a[j][j] = d;
        for i in j + 1..6 {
            a[i][j] = (a[i][j] - dot(&a[i][..j], &a[j][..j])) / d;
        }
    }
    for i in 0..6 {
        b[i] = (b[i] - dot(&a[i][..i], &b[..i])) / a[i][i];
    }
    for i in (0..6).rev() {
        let s: f64 = (i + 1..6).map(|k| a[k][i] * b[k]).sum();
        b[i] = (b[i] - s) / a[i][i];
    }
}

/// The dot product of two slices of one length.
#[inline]
fn dot(x: &[f64], y: &[f64]) -> f64 {
    x.iter().zip(y).map(|(a, b)| a * b).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// With full rank and tiny damping, the step achieves the correction: `J dq = e`.
    #[test]
    fn a_square_jacobian_is_inverted() {
        let columns: Vec<(DVec3, DVec3)> = (0..6)
            .map(|c| {
                let f =
                    |k: usize| ((c * 7 + k * 3) % 11) as f64 / 5.0 - 1.0 + f64::from(c == k) * 2.0;
                (DVec3::new(f(0), f(1), f(2)), DVec3::new(f(3), f(4), f(5)))
            })
            .collect();
        let position = Residual {
            correction: DVec3::new(0.1, -0.2, 0.3),
            projector: DMat3::IDENTITY,
            error: 0.0,
        };
        let orientation = Residual {
            correction: DVec3::new(0.05, 0.0, -0.1),
            ..position
        };
        let mut dq = [0.0; 6];
        dls_step(&columns, &position, &orientation, 1e-12, &mut dq);
        let (mut lin, mut ang) = (DVec3::ZERO, DVec3::ZERO);
        for (d, (a, b)) in dq.iter().zip(&columns) {
            lin += *a * *d;
            ang += *b * *d;
        }
        assert!((lin - position.correction).length() < 1e-8, "{lin}");
        assert!((ang - orientation.correction).length() < 1e-8, "{ang}");
    }

    /// A free block moves nothing on its own: only the constrained rows pull.
    #[test]
    fn free_directions_do_not_pull() {
        let columns = vec![(DVec3::X, DVec3::Z), (DVec3::Y, DVec3::ZERO)];
        let free = Residual::FREE;
        let mut dq = [1.0; 2];
        dls_step(&columns, &free, &free, 1e-6, &mut dq);
        assert_eq!(dq, [0.0, 0.0]);
    }
}
