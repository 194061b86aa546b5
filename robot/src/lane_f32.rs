//! The SIMD type of the arm checks: one `f32` per lane, one lane per configuration of a batch.
//! Shared by `checking` (kinematics, checks, certification) and `scenes` (an obstacle's tests
//! of a batch of points).

/// One `f32` per lane: sixteen lanes where the CPU has 512-bit vectors (AVX-512), eight
/// otherwise. On a Zen 5 machine a batch of sixteen costs about a third more than one of eight
/// (a configuration a third less), an edge's sixteen grid points go in one batch instead of two,
/// and RRT-Connect's median solve on the Panda takes a sixth less time; on AVX2 a batch of
/// sixteen is two halves of eight without the early exit between them, and RRT-Connect a tenth
/// slower (arm-planning reference, "Sixteen lanes on AVX-512"). The lanes' results do not depend
/// on the width: only how many configurations a check evaluates.
#[cfg(target_feature = "avx512f")]
pub(crate) type LaneF32 = wide::f32x16;
/// One `f32` per lane (see the AVX-512 definition).
#[cfg(not(target_feature = "avx512f"))]
pub(crate) type LaneF32 = wide::f32x8;

/// Lanes per batch: the width of [`LaneF32`].
pub(crate) const LANES: usize = std::mem::size_of::<LaneF32>() / 4;
