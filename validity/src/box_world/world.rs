//! [`World`]: axis-aligned box obstacles and anti-obstacles in any dimension (PDT semantics).

use mit_star_spaces::{StateSpace, Stop};

use crate::box_world::box_set::BoxSet;
use crate::{EdgeStatus, MotionProgress, Preparation, Segment, StateValidity, ValidityError};

/// Above this many boxes a world checks states through a bounding-volume hierarchy; at or
/// below it a linear scan of the contiguous rows is as fast. Measured with
/// `LARGE_WORLD_BOXES=32 cargo run --release -p mit-star-validity --example large_world` (and 33): about
/// 160 ns per check in R^4 either way; at 128 boxes the hierarchy is 4–9× faster.
pub const TREE_THRESHOLD: usize = 32;

/// An axis-aligned hyperrectangle given by its centre and full side lengths.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisBox {
    /// Centre, one value per dimension.
    pub center: Vec<f64>,
    /// Full side length per dimension (not half-widths).
    pub widths: Vec<f64>,
}

impl AxisBox {
    /// A box from its centre and full side lengths.
    pub fn new(center: Vec<f64>, widths: Vec<f64>) -> Self {
        Self { center, widths }
    }

    /// A cube of side `side` centred on `center`.
    pub fn cube(center: Vec<f64>, side: f64) -> Self {
        let widths = vec![side; center.len()];
        Self { center, widths }
    }

    /// Closed membership with PDT's tolerance: `|x_d − c_d| ≤ w_d / 2 + ε` for every `d`.
    pub fn contains(&self, state: &[f64]) -> bool {
        state
            .iter()
            .zip(self.center.iter().zip(&self.widths))
            .all(|(&x, (&c, &w))| (x - c).abs() <= 0.5 * w + f64::EPSILON)
    }
}

/// A regular lattice of `count^n` equal cubes: the centres along every dimension are
/// `lower_d + (j + 1) · spacing` for `j = 0 … count-1` (PDT's repeating rectangles). Checked in
/// `O(n)` whatever the number of cubes.
#[derive(Debug, Clone, PartialEq)]
pub struct Lattice {
    /// Cubes per dimension.
    pub count: usize,
    /// Centre-to-centre spacing.
    pub spacing: f64,
    /// Side length of each cube.
    pub side: f64,
}

/// Axis-aligned boxes in a bounded `R^n`: a state is valid iff it lies inside the bounds **and**
/// (inside some anti-obstacle **or** inside no obstacle). Membership is closed, with PDT's
/// machine-epsilon tolerance.
///
/// Boxes are stored as contiguous `[lo₀, hi₀, lo₁, hi₁, …]` rows, so a check is a branch-light
/// scan with early exit and never allocates.
///
/// ```
/// use mit_star_validity::{AxisBox, StateValidity, World};
/// let world = World::new(vec![-0.5; 2], vec![0.5; 2])
///     .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.1, 1.0]))?
///     .with_anti_obstacle(AxisBox::new(vec![0.0, 0.2], vec![0.1, 0.05]))?;
/// assert!(!world.is_valid(&[0.0, 0.0]));  // in the wall
/// assert!(world.is_valid(&[0.0, 0.2]));   // in the gap
/// assert!(!world.is_valid(&[0.7, 0.0]));  // out of bounds
/// # Ok::<(), mit_star_validity::ValidityError>(())
/// ```
#[derive(Debug, Clone)]
pub struct World {
    pub(crate) lower: Vec<f64>,
    pub(crate) upper: Vec<f64>,
    pub(crate) obstacles: BoxSet,
    pub(crate) anti_obstacles: BoxSet,
    pub(crate) lattices: Vec<Lattice>,
}

/// Worlds are equal when they define the same valid set the same way (the hierarchies are
/// caches).
impl PartialEq for World {
    fn eq(&self, other: &Self) -> bool {
        self.lower == other.lower
            && self.upper == other.upper
            && self.obstacles == other.obstacles
            && self.anti_obstacles == other.anti_obstacles
            && self.lattices == other.lattices
    }
}

impl World {
    /// An empty world within the bounds `[lower, upper]` (their lengths give the dimension;
    /// the bounds are taken as given — validate them with a [`StateSpace`] first).
    pub fn new(lower: Vec<f64>, upper: Vec<f64>) -> Self {
        Self {
            lower,
            upper,
            obstacles: BoxSet::default(),
            anti_obstacles: BoxSet::default(),
            lattices: Vec::new(),
        }
    }

    /// An empty world with the bounds of `space`.
    pub fn in_space<S: StateSpace + ?Sized>(space: &S) -> Self {
        Self::new(space.lower().to_vec(), space.upper().to_vec())
    }

    /// Dimension of the world.
    pub fn dimension(&self) -> usize {
        self.lower.len()
    }

    /// Lower bounds.
    pub fn lower(&self) -> &[f64] {
        &self.lower
    }

    /// Upper bounds.
    pub fn upper(&self) -> &[f64] {
        &self.upper
    }

    /// The obstacles, in insertion order.
    pub fn obstacles(&self) -> &[AxisBox] {
        self.obstacles.boxes()
    }

    /// The anti-obstacles, in insertion order.
    pub fn anti_obstacles(&self) -> &[AxisBox] {
        self.anti_obstacles.boxes()
    }

    /// The lattices of cubes.
    pub fn lattices(&self) -> &[Lattice] {
        &self.lattices
    }

    /// Adds an obstacle.
    ///
    /// # Errors
    /// If the box has the wrong dimension, a non-finite centre, or a negative or non-finite width.
    pub fn with_obstacle(mut self, obstacle: AxisBox) -> Result<Self, ValidityError> {
        self.add_obstacle(obstacle)?;
        Ok(self)
    }

    /// Adds an anti-obstacle (free space carved out of obstacles).
    ///
    /// # Errors
    /// As [`with_obstacle`](Self::with_obstacle).
    pub fn with_anti_obstacle(mut self, anti: AxisBox) -> Result<Self, ValidityError> {
        self.add_anti_obstacle(anti)?;
        Ok(self)
    }

    /// Adds a lattice of cubes (obstacles).
    ///
    /// # Errors
    /// If the spacing or side is not finite and positive.
    pub fn with_lattice(mut self, lattice: Lattice) -> Result<Self, ValidityError> {
        for (name, value) in [
            ("lattice spacing", lattice.spacing),
            ("lattice side", lattice.side),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(ValidityError::NotPositive { name, value });
            }
        }
        self.lattices.push(lattice);
        Ok(self)
    }

    /// Builds now the search structures that large worlds' checks use (a hierarchy over the
    /// boxes, and a slab index in many dimensions), which are otherwise built at the first
    /// check after a change: 0.2 s for 10⁵ boxes in R^32, which should not fall in the budget
    /// of the first planner that checks. Clones made afterwards share them.
    /// `mit_star_problems::Problem` calls it when a problem is made.
    pub fn build_indices(&self) {
        let n = self.lower.len();
        self.obstacles.build_indices(n);
        self.anti_obstacles.build_indices(n);
    }

    /// Adds an obstacle in place. Errors as [`with_obstacle`](Self::with_obstacle).
    ///
    /// # Errors
    /// See [`with_obstacle`](Self::with_obstacle).
    pub fn add_obstacle(&mut self, obstacle: AxisBox) -> Result<(), ValidityError> {
        let index = self.obstacles().len();
        self.validate(&obstacle, "obstacle", index)?;
        self.obstacles.push(obstacle);
        Ok(())
    }

    /// Adds an anti-obstacle in place.
    ///
    /// # Errors
    /// See [`with_obstacle`](Self::with_obstacle).
    pub fn add_anti_obstacle(&mut self, anti: AxisBox) -> Result<(), ValidityError> {
        let index = self.anti_obstacles().len();
        self.validate(&anti, "anti-obstacle", index)?;
        self.anti_obstacles.push(anti);
        Ok(())
    }

    fn validate(&self, b: &AxisBox, what: &'static str, index: usize) -> Result<(), ValidityError> {
        let expected = self.dimension();
        for (field, values) in [("center", &b.center), ("widths", &b.widths)] {
            if values.len() != expected {
                return Err(ValidityError::BoxDimension {
                    what,
                    index,
                    field,
                    expected,
                    got: values.len(),
                });
            }
            for (coordinate, &value) in values.iter().enumerate() {
                let requirement = if !value.is_finite() {
                    "it must be finite"
                } else if field == "widths" && value < 0.0 {
                    "widths must not be negative"
                } else {
                    continue;
                };
                return Err(ValidityError::BoxValue {
                    what,
                    index,
                    field,
                    coordinate,
                    value,
                    requirement,
                });
            }
        }
        Ok(())
    }

    #[inline]
    fn in_bounds(&self, state: &[f64]) -> bool {
        state
            .iter()
            .zip(self.lower.iter().zip(&self.upper))
            .all(|(&x, (&lo, &hi))| x >= lo && x <= hi)
    }

    #[inline]
    fn in_lattice(&self, lattice: &Lattice, state: &[f64]) -> bool {
        let half = 0.5 * lattice.side + f64::EPSILON;
        let last = lattice.count as f64 - 1.0;
        state.iter().zip(&self.lower).all(|(&x, &lo)| {
            // Nearest centre index, clamped to the lattice.
            let j = ((x - lo) / lattice.spacing - 1.0).round().clamp(0.0, last);
            (x - (lo + (j + 1.0) * lattice.spacing)).abs() <= half
        })
    }

    /// `true` if the state is inside some obstacle (ignoring anti-obstacles and bounds).
    #[inline]
    pub fn in_obstacle(&self, state: &[f64]) -> bool {
        in_boxes(&self.obstacles, state)
            || self
                .lattices
                .iter()
                .any(|l| l.count > 0 && self.in_lattice(l, state))
    }
}

impl World {
    /// The smallest full side of any obstacle or lattice cube (`None` without obstacles).
    pub fn thinnest_obstacle(&self) -> Option<f64> {
        let cubes = self.lattices.iter().filter(|l| l.count > 0).map(|l| l.side);
        self.obstacles
            .thinnest()
            .into_iter()
            .chain(cubes)
            .reduce(f64::min)
    }

    /// The smallest full side of any anti-obstacle (`None` without anti-obstacles).
    pub fn thinnest_anti_obstacle(&self) -> Option<f64> {
        self.anti_obstacles.thinnest()
    }
}

/// `true` if `state` lies in a box of `set`: the slab index where the hierarchy cannot prune
/// (dimensions at least its depth), else the hierarchy above [`TREE_THRESHOLD`] boxes, else a
/// scan of the rows.
#[inline]
fn in_boxes(set: &BoxSet, state: &[f64]) -> bool {
    if let Some(slabs) = set.slabs(state.len()) {
        return slabs.contains(set.rows(), state);
    }
    match set.hierarchy(state.len()) {
        Some(tree) => tree.contains(state),
        None => in_any(set.rows(), state),
    }
}

/// `true` if `state` lies in any box of `rows` (each box `2n` values).
#[inline]
fn in_any(rows: &[f64], state: &[f64]) -> bool {
    let n2 = 2 * state.len();
    if n2 == 0 {
        return false;
    }
    rows.chunks_exact(n2).any(|row| {
        row.chunks_exact(2)
            .zip(state)
            .all(|(bounds, &x)| x >= bounds[0] && x <= bounds[1])
    })
}

impl StateValidity for World {
    #[inline]
    fn is_valid(&self, state: &[f64]) -> bool {
        // Most states are in no obstacle: test obstacles first, anti-obstacles only on a hit.
        self.in_bounds(state) && (!self.in_obstacle(state) || in_boxes(&self.anti_obstacles, state))
    }

    /// Keeps the boxes whose bounds meet the segment's reach (found through the world's
    /// index) and the bounds it may leave: afterwards each point of the segment is tested
    /// against those boxes only.
    #[inline]
    fn prepare_segment(&self, segment: &mut Segment) -> Preparation {
        self.prepare(segment)
    }

    /// Four points per SIMD step against the boxes the segment kept: bounds along the
    /// coordinates the segment may leave, then the kept obstacles' crossings, then — only for
    /// points inside an obstacle — the kept anti-obstacles'.
    #[inline]
    fn first_invalid_on(&self, segment: &mut Segment, fractions: &[f64]) -> Option<usize> {
        self.first_invalid_on_segment(segment, fractions)
    }

    /// The exact slab tests of [`segment_verdict`](World::segment_verdict), in spaces whose
    /// edges are straight (`None` otherwise), as [`certify_motion_in`](Self::certify_motion_in)
    /// does them, with a scratch of its own: a stopped certification starts over at the next
    /// call (use `certify_motion_in`, as the [`GridWalker`](crate::GridWalker) does, to resume).
    fn certify_motion(
        &self,
        space: &dyn StateSpace,
        a: &[f64],
        b: &[f64],
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        self.certify_motion_in(space, (a, b), &mut Segment::default(), progress, stop)
    }

    /// The exact slab tests of [`segment_verdict`](World::segment_verdict), in spaces whose
    /// edges are straight (`None` otherwise), done in steps: the stop is polled before any
    /// work (a certification begun after it fired tests nothing) and again after every few
    /// microseconds of work (512 units: a box compared with the edge's reach is one, an exact
    /// crossing 32), however many boxes the world has. A stopped certification keeps where it
    /// stands in `scratch` and `progress`, and goes on from there when called again with the
    /// same motion, scratch and progress. The answer is the verdict's whatever the stops.
    fn certify_motion_in(
        &self,
        space: &dyn StateSpace,
        ends: (&[f64], &[f64]),
        scratch: &mut Segment,
        progress: &mut MotionProgress,
        stop: &dyn Stop,
    ) -> Option<EdgeStatus> {
        if !space.is_euclidean() {
            return None;
        }
        Some(self.certify_exact(ends, scratch, progress, stop))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn unit(n: usize) -> World {
        World::new(vec![-0.5; n], vec![0.5; n])
    }

    #[test]
    fn membership_is_closed_with_epsilon() {
        let world = unit(2)
            .with_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.2, 0.2]))
            .unwrap();
        assert!(!world.is_valid(&[0.1, 0.1]));
        assert!(world.is_valid(&[0.1 + 1e-9, 0.0]));
    }

    #[test]
    fn anti_obstacles_carve_free_space() {
        let world = unit(3)
            .with_obstacle(AxisBox::new(vec![0.0; 3], vec![0.4; 3]))
            .unwrap()
            .with_anti_obstacle(AxisBox::new(vec![0.0; 3], vec![0.2; 3]))
            .unwrap();
        assert!(world.is_valid(&[0.0, 0.0, 0.0]));
        assert!(!world.is_valid(&[0.15, 0.0, 0.0]));
        assert!(world.is_valid(&[0.25, 0.0, 0.0]));
    }

    #[test]
    fn lattice_matches_explicit_boxes() {
        let lattice = Lattice {
            count: 4,
            spacing: 0.2,
            side: 0.05,
        };
        let fast = unit(2).with_lattice(lattice).unwrap();
        let mut slow = unit(2);
        for i in 0..4 {
            for j in 0..4 {
                let c = |k: usize| -0.5 + 0.2 * (k as f64 + 1.0);
                slow.add_obstacle(AxisBox::cube(vec![c(i), c(j)], 0.05))
                    .unwrap();
            }
        }
        for k in 0..2000_i32 {
            let x = -0.5 + f64::from(k % 50) / 49.0;
            let y = -0.5 + f64::from(k / 50) / 39.0;
            assert_eq!(fast.is_valid(&[x, y]), slow.is_valid(&[x, y]), "({x}, {y})");
        }
    }

    #[test]
    fn malformed_boxes_are_named() {
        let err = unit(2)
            .with_obstacle(AxisBox::new(vec![0.0, 0.0, 0.0], vec![0.1, 0.1]))
            .unwrap_err();
        assert!(matches!(
            err,
            ValidityError::BoxDimension {
                field: "center",
                got: 3,
                ..
            }
        ));
        let err = unit(2)
            .with_anti_obstacle(AxisBox::new(vec![0.0, 0.0], vec![0.1, -0.1]))
            .unwrap_err();
        assert_eq!(
            err.to_string(),
            "anti-obstacle 0: `widths[1]` is -0.1; widths must not be negative"
        );
    }
}
