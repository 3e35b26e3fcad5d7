//! The default kernel over many rays at once, written branch-free so that the compiler
//! vectorises it, with AVX-512 and AVX2 builds of the same loop chosen at run time on x86-64
//! CPUs that have them.
//!
//! Every lane performs exactly the scalar kernel's operations (the shared pieces of the stable
//! kernel), so each T is bit for bit the one [`crate::transmit`] returns. A
//! lane in total internal reflection computes garbage that is then *selected* away (never
//! multiplied by a mask), so no NaN reaches its output or its neighbours.
//!
//! The rays are stored in blocks of [`LANES`] (structure-of-arrays within a block, an array of
//! blocks around them), each block a few whole cache lines. With one array per quantity (seven
//! in, four out) the columns' addresses fell at nearly the same offset within a 4 KiB page
//! wherever the allocator put them, so that eleven streams competed for the same few sets of
//! the L1 cache, and the in-cache time per ray varied by a third from run to run. Blocks are one
//! stream in and two out, aligned, and give the vectorised loop a fixed trip count of sixteen
//! lanes: one 512-bit vector of f32, or two or four independent 256-bit ones, whose chains of
//! arithmetic the processor overlaps.

use super::real::{Real, Vector3};
use super::stable::Unturned;

/// Rays per block (a power of two).
pub const LANES: usize = 16;
const _: () = assert!(LANES.is_power_of_two(), "LANES must be a power of two");

/// [`LANES`] rays: unit travel directions (x, y and z rows), unit normals (either side), μ.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C, align(64))]
pub struct RayBlock<S: Real> {
    /// The travel directions' x, y and z components, one row each.
    pub d: [[S; LANES]; 3],
    /// The normals' x, y and z components, one row each.
    pub n: [[S; LANES]; 3],
    /// μ = `μ_i/μ_t` per ray.
    pub mu: [S; LANES],
}

impl<S: Real> RayBlock<S> {
    /// Lanes not yet filled hold a ray straight down through a flat surface at μ = 1, which
    /// transmits unchanged: nothing unusual is computed for them.
    fn padding() -> Self {
        Self {
            d: [[S::ZERO; LANES], [-S::ONE; LANES], [S::ZERO; LANES]],
            n: [[S::ZERO; LANES], [S::ONE; LANES], [S::ZERO; LANES]],
            mu: [S::ONE; LANES],
        }
    }
}

/// Rays in blocks of [`LANES`]: unit travel directions, unit normals (either side), μ.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct RayBatch<S: Real> {
    blocks: Vec<RayBlock<S>>,
    len: usize,
}

impl<S: Real> RayBatch<S> {
    /// An empty batch.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::batch::RayBatch;
    /// let rays = RayBatch::<f64>::new();
    /// assert!(rays.is_empty() && rays.blocks().is_empty());
    /// ```
    #[must_use]
    pub fn new() -> Self {
        Self {
            blocks: Vec::new(),
            len: 0,
        }
    }

    /// Adds a ray: unit travel direction `d`, unit normal `n` (either side), index ratio `mu`
    /// (as accepted by [`crate::transmit`]; not checked).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::batch::RayBatch;
    /// let mut rays = RayBatch::<f32>::new();
    /// rays.push(Vec3::new(0.6, -0.8, 0.0), Vec3::Y, 1.0 / 1.5);
    /// assert_eq!(rays.get(0), (Vec3::new(0.6, -0.8, 0.0), Vec3::Y, 1.0 / 1.5));
    /// ```
    pub fn push(&mut self, d: S::Vec3, n: S::Vec3, mu: S) {
        let lane = self.len % LANES;
        if lane == 0 {
            self.blocks.push(RayBlock::padding());
        }
        let block = self.blocks.last_mut().expect("a block was pushed above");
        for (row, value) in block.d.iter_mut().zip(d.to_array()) {
            row[lane] = value;
        }
        for (row, value) in block.n.iter_mut().zip(n.to_array()) {
            row[lane] = value;
        }
        block.mu[lane] = mu;
        self.len += 1;
    }

    /// The number of rays.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::batch::{LANES, RayBatch};
    /// let mut rays = RayBatch::<f64>::new();
    /// for _ in 0..LANES + 1 {
    ///     rays.push(DVec3::NEG_Y, DVec3::Y, 1.5);
    /// }
    /// assert_eq!((rays.len(), rays.blocks().len()), (LANES + 1, 2));
    /// ```
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether the batch holds no ray.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::batch::RayBatch;
    /// let mut rays = RayBatch::<f64>::new();
    /// assert!(rays.is_empty());
    /// rays.push(DVec3::NEG_Y, DVec3::Y, 1.5);
    /// assert!(!rays.is_empty());
    /// ```
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// The blocks: ray `i` is lane `i % LANES` of block `i / LANES`. The last block's lanes
    /// from `len() % LANES` on (if that is not 0) are padding.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::batch::RayBatch;
    /// let mut rays = RayBatch::<f32>::new();
    /// rays.push(Vec3::new(0.6, -0.8, 0.0), Vec3::Y, 1.5);
    /// let block = &rays.blocks()[0];
    /// assert_eq!((block.d[0][0], block.d[1][0], block.mu[0]), (0.6, -0.8, 1.5));
    /// assert_eq!(block.mu[1], 1.0); // padding: a ray that goes straight through
    /// ```
    #[must_use]
    pub fn blocks(&self) -> &[RayBlock<S>] {
        &self.blocks
    }

    /// Ray `i`: (d, n, μ).
    ///
    /// # Panics
    /// If `i >= len()`.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::batch::RayBatch;
    /// let mut rays = RayBatch::<f64>::new();
    /// rays.push(DVec3::NEG_Y, DVec3::Y, 1.5);
    /// rays.push(DVec3::NEG_X, DVec3::X, 2.0);
    /// assert_eq!(rays.get(1), (DVec3::NEG_X, DVec3::X, 2.0));
    /// ```
    #[must_use]
    pub fn get(&self, i: usize) -> (S::Vec3, S::Vec3, S) {
        assert!(i < self.len, "ray {i} of a batch of {}", self.len);
        let (block, lane) = (&self.blocks[i / LANES], i % LANES);
        let [dx, dy, dz] = block.d.map(|row| row[lane]);
        let [nx, ny, nz] = block.n.map(|row| row[lane]);
        (
            S::Vec3::new(dx, dy, dz),
            S::Vec3::new(nx, ny, nz),
            block.mu[lane],
        )
    }
}

/// The transmitted directions of one [`RayBlock`]: x, y and z rows (zero where totally
/// internally reflected).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(C, align(64))]
pub struct TransmittedBlock<S: Real> {
    /// T's x, y and z components, one row each.
    pub t: [[S; LANES]; 3],
}

/// The results of a batch: T per ray (zero where totally internally reflected) and the TIR
/// flags, in blocks of [`LANES`] like the rays.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Transmissions<S: Real> {
    blocks: Vec<TransmittedBlock<S>>,
    tir: Vec<[bool; LANES]>,
    len: usize,
}

impl<S: Real> Transmissions<S> {
    /// Room for the results of `rays`, every ray marked as not yet computed (zero, not TIR).
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::batch::{RayBatch, Transmissions};
    /// let mut rays = RayBatch::<f32>::new();
    /// rays.push(Vec3::NEG_Y, Vec3::Y, 1.5);
    /// let out = Transmissions::for_batch(&rays);
    /// assert_eq!((out.len(), out.get(0)), (1, Some(Vec3::ZERO)));
    /// ```
    #[must_use]
    pub fn for_batch(rays: &RayBatch<S>) -> Self {
        Self::zeroed(rays.len())
    }

    /// Room for `len` results, each zero and not TIR: for answers computed elsewhere and
    /// written with [`Transmissions::set`].
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::batch::Transmissions;
    /// let out = Transmissions::<f64>::zeroed(3);
    /// assert_eq!(out.len(), 3);
    /// assert_eq!(out.get(2), Some(glam::DVec3::ZERO));
    /// ```
    #[must_use]
    pub fn zeroed(len: usize) -> Self {
        let mut out = Self {
            blocks: Vec::new(),
            tir: Vec::new(),
            len: 0,
        };
        out.resize(len);
        out
    }

    /// The number of results.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::batch::Transmissions;
    /// assert_eq!(Transmissions::<f32>::zeroed(20).len(), 20);
    /// ```
    #[must_use]
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there are no results.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::batch::Transmissions;
    /// assert!(Transmissions::<f32>::zeroed(0).is_empty());
    /// assert!(!Transmissions::<f32>::zeroed(1).is_empty());
    /// ```
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Result `i`: T, or `None` on total internal reflection.
    ///
    /// # Panics
    /// If `i >= len()`.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::Vec3;
    /// use refraction_kernel::batch::{RayBatch, Transmissions, transmit_batch};
    /// let mut rays = RayBatch::<f32>::new();
    /// rays.push(Vec3::new(0.8, -0.6, 0.0), Vec3::Y, 1.5); // past the critical angle
    /// rays.push(Vec3::NEG_Y, Vec3::Y, 1.5);
    /// let mut out = Transmissions::for_batch(&rays);
    /// transmit_batch(&rays, &mut out);
    /// assert_eq!((out.get(0), out.get(1)), (None, Some(Vec3::NEG_Y)));
    /// ```
    #[must_use]
    pub fn get(&self, i: usize) -> Option<S::Vec3> {
        assert!(i < self.len, "result {i} of {}", self.len);
        let (block, lane) = (i / LANES, i % LANES);
        let [x, y, z] = self.blocks[block].t.map(|row| row[lane]);
        (!self.tir[block][lane]).then(|| S::Vec3::new(x, y, z))
    }

    /// Sets result `i`: T, or `None` for total internal reflection (stored as zero).
    ///
    /// # Panics
    /// If `i >= len()`.
    ///
    /// # Examples
    ///
    /// ```
    /// use glam::DVec3;
    /// use refraction_kernel::batch::Transmissions;
    /// let mut out = Transmissions::<f64>::zeroed(2);
    /// out.set(0, Some(DVec3::X));
    /// out.set(1, None);
    /// assert_eq!((out.get(0), out.get(1)), (Some(DVec3::X), None));
    /// ```
    pub fn set(&mut self, i: usize, t: Option<S::Vec3>) {
        assert!(i < self.len, "result {i} of {}", self.len);
        let (block, lane) = (i / LANES, i % LANES);
        let values = t.map_or([S::ZERO; 3], Vector3::to_array);
        for (row, value) in self.blocks[block].t.iter_mut().zip(values) {
            row[lane] = value;
        }
        self.tir[block][lane] = t.is_none();
    }

    /// The blocks to write: T per [`RayBlock`] and its TIR flags, laid out like
    /// [`RayBatch::blocks`].
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::batch::Transmissions;
    /// let mut out = Transmissions::<f32>::zeroed(3);
    /// let (blocks, tir) = out.blocks_mut();
    /// blocks[0].t[0][2] = 1.0; // x of ray 2
    /// tir[0][1] = true;
    /// assert_eq!(out.get(2), Some(glam::Vec3::X));
    /// assert_eq!(out.get(1), None);
    /// ```
    pub fn blocks_mut(&mut self) -> (&mut [TransmittedBlock<S>], &mut [[bool; LANES]]) {
        (&mut self.blocks, &mut self.tir)
    }

    fn resize(&mut self, len: usize) {
        let blocks = len.div_ceil(LANES);
        let zero = TransmittedBlock {
            t: [[S::ZERO; LANES]; 3],
        };
        self.blocks.resize(blocks, zero);
        self.tir.resize(blocks, [false; LANES]);
        self.len = len;
    }
}

/// One lane: [`crate::transmit`]'s arithmetic without branches. Returns (T or zero, TIR).
#[inline(always)]
fn lane<S: Real>(d: S::Vec3, n: S::Vec3, mu: S) -> (S::Vec3, bool) {
    let unturned = Unturned::new(d, n, mu);
    let equal = mu == S::ONE;
    let tir = unturned.k < S::ZERO && !equal;
    // A lane in total internal reflection takes the root of a negative k: its NaN is selected
    // away below, like the whole T of a lane at μ = 1.
    let t = unturned.direction(unturned.k.sqrt());
    let t = if equal { d } else { t };
    let zero = S::Vec3::new(S::ZERO, S::ZERO, S::ZERO);
    (if tir { zero } else { t }, tir)
}

/// Lane `j` of `block`: (d, n, μ).
#[inline(always)]
fn ray_at<S: Real>(block: &RayBlock<S>, j: usize) -> (S::Vec3, S::Vec3, S) {
    let [dx, dy, dz] = &block.d;
    let [nx, ny, nz] = &block.n;
    (
        S::Vec3::new(dx[j], dy[j], dz[j]),
        S::Vec3::new(nx[j], ny[j], nz[j]),
        block.mu[j],
    )
}

/// Writes lane `j`'s answer.
#[inline(always)]
fn answer_at<S: Real>(
    out: &mut TransmittedBlock<S>,
    tir: &mut [bool; LANES],
    j: usize,
    (t, reflected): (S::Vec3, bool),
) {
    let [tx, ty, tz] = &mut out.t;
    [tx[j], ty[j], tz[j]] = t.to_array();
    tir[j] = reflected;
}

/// Runs `lane` on every lane of every block of `rays` one at a time (padding included: it is
/// harmless), writing `out` (which must have as many blocks), as a ray tracer calls a scalar
/// kernel: the loop of the scalar variants. `lane_index` sees every lane index before use;
/// `std::hint::black_box` there keeps each ray a call of its own (the compiler would otherwise
/// vectorise across rays).
#[inline(always)]
pub(crate) fn for_each_ray<S: Real>(
    rays: &RayBatch<S>,
    out: &mut Transmissions<S>,
    lane_index: impl Fn(usize) -> usize,
    lane: impl Fn(S::Vec3, S::Vec3, S) -> (S::Vec3, bool),
) {
    let blocks = out.blocks.iter_mut().zip(&mut out.tir);
    for (block, (answers, tir)) in rays.blocks.iter().zip(blocks) {
        for j in 0..LANES {
            // LANES is a power of two: the mask keeps the index in range without a check.
            let j = lane_index(j) & (LANES - 1);
            let (d, n, mu) = ray_at(block, j);
            answer_at(answers, tir, j, lane(d, n, mu));
        }
    }
}

/// The batch kernel's loop: every lane of every block, padding included, with a fixed trip
/// count of [`LANES`] that the compiler vectorises whole.
#[inline(always)]
fn transmit_blocks<S: Real>(rays: &RayBatch<S>, out: &mut Transmissions<S>) {
    for_each_ray(rays, out, |j| j, lane);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn transmit_blocks_avx2<S: Real>(rays: &RayBatch<S>, out: &mut Transmissions<S>) {
    transmit_blocks(rays, out);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx512vl,avx512bw,avx512dq")]
fn transmit_blocks_avx512<S: Real>(rays: &RayBatch<S>, out: &mut Transmissions<S>) {
    transmit_blocks(rays, out);
}

/// A build of the batch kernel's loop: the same arithmetic (so the same bits) compiled for one
/// instruction set.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Build {
    /// For the target the crate is compiled for (SSE2 on plain x86-64): runs everywhere.
    Portable,
    /// 256-bit AVX2 vectors: eight f32 lanes (x86-64 CPUs that have it).
    Avx2,
    /// 512-bit AVX-512 (F, VL, BW, DQ) vectors: sixteen f32 lanes, one block per vector, with
    /// mask registers for the selects (x86-64 CPUs that have it).
    Avx512,
}

impl Build {
    /// Every build, slowest first.
    pub const ALL: [Self; 3] = [Self::Portable, Self::Avx2, Self::Avx512];

    /// The short name used in reports: `"portable"`, `"avx2"`, `"avx512"`.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::batch::Build;
    /// assert_eq!(Build::ALL.map(Build::name), ["portable", "avx2", "avx512"]);
    /// ```
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Portable => "portable",
            Self::Avx2 => "avx2",
            Self::Avx512 => "avx512",
        }
    }

    /// Whether this CPU can run the build.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::batch::Build;
    /// assert!(Build::Portable.is_available());
    /// // A CPU with AVX-512 has AVX2 too.
    /// assert!(!Build::Avx512.is_available() || Build::Avx2.is_available());
    /// ```
    #[must_use]
    pub fn is_available(self) -> bool {
        match self {
            Self::Portable => true,
            #[cfg(target_arch = "x86_64")]
            Self::Avx2 => std::arch::is_x86_feature_detected!("avx2"),
            #[cfg(target_arch = "x86_64")]
            Self::Avx512 => {
                std::arch::is_x86_feature_detected!("avx512f")
                    && std::arch::is_x86_feature_detected!("avx512vl")
                    && std::arch::is_x86_feature_detected!("avx512bw")
                    && std::arch::is_x86_feature_detected!("avx512dq")
            }
            #[cfg(not(target_arch = "x86_64"))]
            Self::Avx2 | Self::Avx512 => false,
        }
    }

    /// The widest build this CPU can run: the one [`transmit_batch`] uses.
    ///
    /// # Examples
    ///
    /// ```
    /// use refraction_kernel::batch::Build;
    /// let widest = Build::widest();
    /// assert!(widest.is_available());
    /// println!("the batch kernel runs its {} build here", widest.name());
    /// ```
    #[must_use]
    pub fn widest() -> Self {
        Self::ALL
            .into_iter()
            .rev()
            .find(|build| build.is_available())
            .unwrap_or(Self::Portable)
    }
}

/// Refracts every ray of `rays` into `out` (resized to match) with the widest build of the loop
/// this CPU runs ([`Build::widest`]); each T equals [`crate::transmit`]'s bit for bit. The
/// preconditions are [`crate::transmit`]'s, not checked.
///
/// # Examples
///
/// ```
/// use glam::Vec3;
/// use refraction_kernel::batch::{RayBatch, Transmissions, transmit_batch};
/// let mut rays = RayBatch::<f32>::new();
/// let d = Vec3::new(0.6, -0.8, 0.0);
/// rays.push(d, Vec3::Y, 1.0 / 1.5);
/// rays.push(d, -Vec3::Y, 1.0 / 1.5); // the normal on either side
/// let mut out = Transmissions::default(); // resized to match
/// transmit_batch(&rays, &mut out);
/// let t = refraction_kernel::transmit(d, Vec3::Y, 1.0 / 1.5);
/// assert_eq!((out.get(0), out.get(1)), (t, t));
/// ```
pub fn transmit_batch<S: Real>(rays: &RayBatch<S>, out: &mut Transmissions<S>) {
    transmit_batch_with(Build::widest(), rays, out);
}

/// [`transmit_batch`] with a chosen build, to compare them. Every build gives the same bits.
///
/// # Panics
/// If `build` is not available on this CPU ([`Build::is_available`]).
///
/// # Examples
///
/// ```
/// use glam::DVec3;
/// use refraction_kernel::batch::{Build, RayBatch, Transmissions, transmit_batch_with};
/// let mut rays = RayBatch::<f64>::new();
/// rays.push(DVec3::new(0.6, -0.8, 0.0), DVec3::Y, 1.0 / 1.5);
/// let mut portable = Transmissions::for_batch(&rays);
/// transmit_batch_with(Build::Portable, &rays, &mut portable);
/// let mut widest = Transmissions::for_batch(&rays);
/// transmit_batch_with(Build::widest(), &rays, &mut widest);
/// assert_eq!(portable, widest);
/// ```
pub fn transmit_batch_with<S: Real>(build: Build, rays: &RayBatch<S>, out: &mut Transmissions<S>) {
    assert!(
        build.is_available(),
        "the {} build needs a CPU that has it",
        build.name()
    );
    out.resize(rays.len());
    match build {
        Build::Portable => transmit_blocks(rays, out),
        #[cfg(target_arch = "x86_64")]
        #[expect(
            unsafe_code,
            reason = "a target_feature function, called where the CPU has it"
        )]
        Build::Avx2 => {
            // SAFETY: the CPU supports AVX2 (is_available, asserted above).
            unsafe { transmit_blocks_avx2(rays, out) }
        }
        #[cfg(target_arch = "x86_64")]
        #[expect(
            unsafe_code,
            reason = "a target_feature function, called where the CPU has it"
        )]
        Build::Avx512 => {
            // SAFETY: the CPU supports these AVX-512 subsets (is_available, asserted above).
            unsafe { transmit_blocks_avx512(rays, out) }
        }
        #[cfg(not(target_arch = "x86_64"))]
        Build::Avx2 | Build::Avx512 => unreachable!("no x86-64 build is available here"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stable::transmit;
    use glam::Vec3;

    #[test]
    fn a_tir_lane_leaves_its_neighbours_alone() {
        let mut rays = RayBatch::<f32>::new();
        let n = Vec3::Y;
        let steep = Vec3::new(0.6, -0.8, 0.0);
        let shallow = Vec3::new(0.8, -0.6, 0.0);
        for (d, mu) in [
            (steep, 1.5),
            (shallow, 1.5),
            (steep, 1.0 / 1.5),
            (Vec3::X, 1.5),
            (Vec3::X, 1.0),
        ] {
            rays.push(d, n, mu);
        }
        let mut out = Transmissions::for_batch(&rays);
        transmit_batch(&rays, &mut out);
        for i in 0..rays.len() {
            let (d, n, mu) = rays.get(i);
            assert_eq!(out.get(i), transmit(d, n, mu), "lane {i}");
        }
        assert_eq!(out.get(1), None);
        assert_eq!(out.get(3), None);
        assert_eq!(out.get(4), Some(Vec3::X));
    }

    /// A point of the unit sphere from two numbers in [0, 1).
    fn sphere(u: f64, v: f64) -> glam::DVec3 {
        let z = 2.0 * u - 1.0;
        let r = (1.0 - z * z).sqrt();
        let phi = core::f64::consts::TAU * v;
        glam::DVec3::new(r * phi.cos(), r * phi.sin(), z)
    }

    /// Rays of every kind, normals on both sides, from a low-discrepancy sequence: any angle,
    /// within 1e-9 of normal incidence, grazing, μ from 1e-12 to 1e12 and exactly 1, TIR; the
    /// count leaves the last block part-filled.
    fn awkward<S: Real>() -> RayBatch<S> {
        let frac = |x: f64| x - x.floor();
        let to_s =
            |v: glam::DVec3| S::Vec3::new(S::from_f64(v.x), S::from_f64(v.y), S::from_f64(v.z));
        let mut rays = RayBatch::new();
        for i in 0..(250 * LANES + 7) {
            let x = i as f64;
            let n = sphere(frac(x * 0.618_034), frac(x * 0.754_878));
            let any = sphere(frac(x * 0.569_840), frac(x * 0.438_110));
            let d = match i % 4 {
                0 => (-n + any * 1e-9).normalize(),
                1 => (any - n * any.dot(n) + n * 1e-9).normalize(),
                _ => any,
            };
            let mu = if i % 7 == 0 {
                1.0
            } else {
                10f64.powf(24.0 * frac(x * 0.381_966) - 12.0)
            };
            rays.push(to_s(d), to_s(n), S::from_f64(mu));
        }
        rays
    }

    fn bits<S: Real>(t: S::Vec3) -> [u64; 3] {
        t.to_array().map(|c| c.to_f64().to_bits())
    }

    fn every_build_equals_transmit<S: Real>() {
        let rays = awkward::<S>();
        let builds = Build::ALL.into_iter().filter(|b| b.is_available());
        for build in builds {
            let name = build.name();
            let mut out = Transmissions::for_batch(&rays);
            transmit_batch_with(build, &rays, &mut out);
            for i in 0..rays.len() {
                let (d, n, mu) = rays.get(i);
                let scalar = transmit(d, n, mu);
                assert_eq!(
                    out.get(i).map(bits::<S>),
                    scalar.map(bits::<S>),
                    "{name} {} ray {i}",
                    S::NAME
                );
            }
        }
    }

    #[test]
    fn every_build_of_the_loop_equals_the_scalar_kernel_bit_for_bit() {
        every_build_equals_transmit::<f32>();
        every_build_equals_transmit::<f64>();
    }

    #[test]
    fn rays_fill_blocks_lane_by_lane_and_read_back_as_pushed() {
        let mut rays = RayBatch::<f64>::new();
        for i in 0..(2 * LANES + 3) {
            let x = i as f64;
            rays.push(glam::DVec3::new(x, -1.0, 0.5), glam::DVec3::Z, 1.0 + x);
        }
        assert_eq!((rays.len(), rays.blocks().len()), (2 * LANES + 3, 3));
        assert_eq!(rays.blocks()[1].d[0][2], (LANES + 2) as f64);
        assert_eq!(rays.blocks()[2], {
            let mut last = RayBlock::padding();
            for j in 0..3 {
                last.d[0][j] = (2 * LANES + j) as f64;
                last.d[1][j] = -1.0;
                last.d[2][j] = 0.5;
                last.n[1][j] = 0.0;
                last.n[2][j] = 1.0;
                last.mu[j] = (2 * LANES + j + 1) as f64;
            }
            last
        });
        let (d, n, mu) = rays.get(LANES + 5);
        assert_eq!(d, glam::DVec3::new((LANES + 5) as f64, -1.0, 0.5));
        assert_eq!((n, mu), (glam::DVec3::Z, (LANES + 6) as f64));
    }

    #[test]
    fn results_set_one_by_one_read_back() {
        let mut out = Transmissions::<f32>::zeroed(LANES + 1);
        out.set(LANES, Some(Vec3::X));
        out.set(3, None);
        assert_eq!(out.get(LANES), Some(Vec3::X));
        assert_eq!(out.get(3), None);
        assert_eq!(out.get(0), Some(Vec3::ZERO));
    }

    #[test]
    #[should_panic(expected = "ray 3 of a batch of 3")]
    fn a_ray_past_the_end_is_refused_though_its_lane_exists() {
        let mut rays = RayBatch::<f32>::new();
        for _ in 0..3 {
            rays.push(Vec3::NEG_Y, Vec3::Y, 1.5);
        }
        assert!(rays.get(3).2 > 0.0, "not reached");
    }
}
