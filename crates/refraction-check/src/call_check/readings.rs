//! The argument mistakes: every way of reading a call's arguments as a right call with up to
//! all four argument mistakes undone, kept when it fits the API's contract and the truth, the
//! fewest mistakes first and the likeliest of those first.

use glam::DVec3;
use refraction_kernel::api::{Api, Args, Meaning};

use super::call::{Call, Digits};
use crate::diagnosis::Code;
use refraction_tools::vector_text::{angle, length, unit};

/// The mistakes a call's arguments can have, in the order they are undone.
const ARGUMENT_MISTAKES: [Code; 4] = [
    Code::EtaInverted,
    Code::IncidentReversed,
    Code::NormalNotFacing,
    Code::NotUnitInput,
];

/// Relative rounding of a number written with `digits` significant digits: half a unit in
/// the last digit written. Few digits are a value, not a rounding: a number written with one
/// or two (`1.5`, `0`, a vector `0.6, -0.8, 0`) is taken as exact, as are 17 digits or more
/// (and 0, for a number without digits); a format's precision shows in longer numbers.
fn rounding(digits: u32) -> f64 {
    if digits <= 2 || digits >= 17 {
        0.0
    } else {
        0.5 * 10f64.powi(1 - i32::try_from(digits).unwrap_or(17))
    }
}

/// Relative rounding of a number written with `digits` significant digits where a fixed
/// format may have printed it (`decimal`: it shows a point or an exponent): half a unit in
/// the last digit, however few digits (`0.6` printed by `%.1f` is anything from 0.55 to 0.65).
/// Numbers without a point (`0`, `1`) say what they are.
pub(crate) fn loose_rounding(digits: u32, decimal: bool) -> f64 {
    if !decimal || digits == 0 || digits >= 17 {
        rounding(digits)
    } else {
        0.5 * 10f64.powi(1 - i32::try_from(digits).unwrap_or(17))
    }
}

/// The most significant digits of a call's numbers at which its short numbers (`0.6`) may be
/// a fixed format's rounding (`%.1f`, Unity's "F2" at most 3 carried digits) rather than
/// the values they say.
pub(crate) const FIXED_FORMAT_DIGITS: u32 = 3;

/// How closely each logged number can be trusted: its own rounding, or a few ulps of the
/// student's working precision.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Tolerance {
    /// Relative rounding of the incident vector as logged.
    pub incident: f64,
    /// Relative rounding of the normal.
    pub normal: f64,
    /// Relative rounding of the index ratio.
    pub eta: f64,
    /// Relative rounding of what came back.
    pub result: f64,
    /// Relative rounding of the logged direction of travel.
    pub travel: f64,
    /// The machine epsilon of the student's working precision.
    pub epsilon: f64,
    /// Whether this is the second look at a call the first judged wrong: every number trusted
    /// only as far as its printed digits go (a short one too), and a sign the digits cannot
    /// decide (of N·I against the API's contract) taken either way.
    pub loose: bool,
}

impl Tolerance {
    /// The tolerance for numbers written with `digits` in a precision with machine epsilon
    /// `epsilon`.
    #[must_use]
    pub(crate) fn new(digits: &Digits, epsilon: f64) -> Self {
        Self {
            incident: rounding(digits.incident),
            normal: rounding(digits.normal),
            eta: rounding(digits.eta),
            result: rounding(digits.result),
            travel: rounding(digits.travel),
            epsilon,
            loose: false,
        }
    }

    /// The tolerance of [`Tolerance::loose`]: each number trusted to its printed digits and no
    /// further, however few.
    #[must_use]
    pub(crate) fn loose(digits: &Digits, epsilon: f64) -> Self {
        let d = &digits.decimal;
        // A short number beside longer vectors was printed by a shortest-text format (`%g`):
        // it is the value it says. Beside vectors as short, it may be a fixed format's
        // rounding.
        let finest = [digits.incident, digits.normal, digits.result]
            .into_iter()
            .filter(|&n| n < 17)
            .max()
            .unwrap_or(0);
        let fixed = |n: u32, decimal: bool| decimal && (n > 2 || finest <= FIXED_FORMAT_DIGITS);
        Self {
            incident: loose_rounding(digits.incident, fixed(digits.incident, d.incident)),
            normal: loose_rounding(digits.normal, fixed(digits.normal, d.normal)),
            eta: loose_rounding(digits.eta, fixed(digits.eta, d.eta)),
            result: loose_rounding(digits.result, fixed(digits.result, d.result)),
            travel: loose_rounding(digits.travel, d.travel && digits.travel > 2),
            epsilon,
            loose: true,
        }
    }

    /// Whether the sign of the cosine between `a` and `b` (N·I) cannot be told from their
    /// printed digits: only on a second look.
    #[must_use]
    pub(crate) fn sign_undecided(&self, a: DVec3, b: DVec3) -> bool {
        let lengths = length(a) * length(b);
        let margin = 4.0 * (self.incident + self.normal) + 16.0 * self.epsilon;
        self.loose && lengths > 0.0 && (a.dot(b) / lengths).abs() <= margin
    }

    /// The coarsest rounding of the call's arguments, by which they may be moved.
    #[must_use]
    pub(crate) fn arguments(&self) -> f64 {
        self.incident.max(self.normal).max(self.eta)
    }

    /// The relative error a number rounded by `rounding` may carry, or a few ulps.
    fn relative(&self, rounding: f64) -> f64 {
        4.0 * rounding + 16.0 * self.epsilon
    }

    /// Whether the incident vector and the normal are unit length, each within its own
    /// rounding.
    #[must_use]
    pub(crate) fn unit_arguments(&self, args: &Args<f64>) -> bool {
        (length(args.incident) - 1.0).abs() <= self.relative(self.incident)
            && (length(args.normal) - 1.0).abs() <= self.relative(self.normal)
    }

    /// Whether a ratio derived from the logged eta is `mu` as given.
    #[must_use]
    pub(crate) fn same_ratio(&self, a: f64, b: f64) -> bool {
        (a / b - 1.0).abs() <= self.relative(self.eta)
    }

    /// Whether the direction of travel derived from the incident vector is the logged one (a
    /// tracer's own direction may be written with fewer digits, and unnormalised).
    #[must_use]
    pub(crate) fn same_direction(&self, a: DVec3, b: DVec3) -> bool {
        angle(a, b) <= (8.0 * self.incident.max(self.travel)).max(1e-3)
    }
}

/// One reading of the arguments: the mistakes it assumes and the call without them.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Reading {
    /// The argument mistakes assumed: eta, incident, normal, unit, in that order.
    pub codes: Vec<Code>,
    /// The arguments with those mistakes undone: the right call.
    pub args: Args<f64>,
    /// What the right call means.
    pub meaning: Meaning<f64>,
}

/// The arguments with `codes` undone.
#[must_use]
pub(crate) fn undo(codes: &[Code], args: Args<f64>) -> Args<f64> {
    let mut right = args;
    for code in codes {
        match code {
            Code::EtaInverted => right.eta = 1.0 / right.eta,
            Code::IncidentReversed => right.incident = -right.incident,
            Code::NormalNotFacing => right.normal = -right.normal,
            Code::NotUnitInput => {
                right.incident = unit(right.incident);
                right.normal = unit(right.normal);
            }
            // Result mistakes: the arguments are as the call passed them.
            Code::NotTheApiResult
            | Code::MissedTir
            | Code::NoFlipInside
            | Code::NormalTermSign
            | Code::OtherRoot
            | Code::FalseTir
            | Code::AcrossSign
            | Code::RefractedTwice
            | Code::FresnelCosSign
            | Code::NormalsMixed => {}
        }
    }
    right
}

/// The reading with `codes` if it fits: `not_unit_input` exactly when an input is not unit,
/// the API's contract, and every truth given.
fn fit(call: &Call, codes: Vec<Code>, tolerance: &Tolerance) -> Option<Reading> {
    let unit_input = tolerance.unit_arguments(&call.args);
    if codes.contains(&Code::NotUnitInput) == unit_input {
        return None;
    }
    let args = undo(&codes, call.args);
    let meaning = call.api.meaning(args);
    let truth = &call.truth;
    let contract =
        meaning.within_contract || tolerance.sign_undecided(call.args.incident, call.args.normal);
    let fits = contract
        && truth
            .travel
            .is_none_or(|t| tolerance.same_direction(meaning.travel, t))
        && truth
            .mu()
            .is_none_or(|mu| tolerance.same_ratio(meaning.mu, mu));
    fits.then_some(Reading {
        codes,
        args,
        meaning,
    })
}

/// Whether the logged normal points into the object under `reading` (pbrt and Mitsuba, with
/// `entering` logged): a ray entering travels against the outward normal.
#[must_use]
pub(crate) fn normal_points_inward(call: &Call, reading: &Reading) -> bool {
    matches!(call.api, Api::Pbrt | Api::Mitsuba)
        && !call.truth.entering_from_normal
        && call.truth.entering.is_some_and(|entering| {
            (call.args.normal.dot(reading.meaning.travel) > 0.0) == entering
        })
}

/// How unlikely a reading is in this API (lower is likelier), from the issue threads: eta
/// upside down and an unflipped normal lead in GLSL and the book; the sign of wi leads in pbrt
/// and Mitsuba, where an inward normal is the likelier of the two ways to get eta's side wrong.
fn cost(call: &Call, reading: &Reading) -> i32 {
    let inward = normal_points_inward(call, reading);
    let one = |code: Code| match (call.api, code) {
        (Api::Glsl | Api::Rtiow, Code::EtaInverted) => 0,
        (Api::Glsl | Api::Rtiow, Code::NormalNotFacing) => 2,
        (Api::Glsl | Api::Rtiow, Code::IncidentReversed) => 4,
        (Api::Pbrt | Api::Mitsuba, Code::IncidentReversed) => 0,
        (Api::Pbrt | Api::Mitsuba, Code::NormalNotFacing) if inward => 1,
        (Api::Pbrt | Api::Mitsuba, Code::EtaInverted) => 2,
        (Api::Pbrt | Api::Mitsuba, Code::NormalNotFacing) => 4,
        _ => 6,
    };
    reading.codes.iter().map(|&c| one(c)).sum()
}

/// Every reading with the fewest argument mistakes that fits, the likeliest first; empty when
/// no combination of the four fits the truth.
#[must_use]
pub(crate) fn readings(call: &Call, tolerance: &Tolerance) -> Vec<Reading> {
    for size in 0..=ARGUMENT_MISTAKES.len() {
        let mut found: Vec<Reading> = (0..1_u32 << ARGUMENT_MISTAKES.len())
            .filter(|mask| mask.count_ones() as usize == size)
            .filter_map(|mask| {
                let codes = ARGUMENT_MISTAKES
                    .iter()
                    .enumerate()
                    .filter(|(i, _)| mask & (1 << i) != 0)
                    .map(|(_, code)| *code)
                    .collect();
                fit(call, codes, tolerance)
            })
            .collect();
        if !found.is_empty() {
            found.sort_by_key(|r| cost(call, r));
            return found;
        }
    }
    Vec::new()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::call_check::call::{Got, Truth};
    use refraction_tools::Precision;

    fn glsl(i: DVec3, n: DVec3, eta: f64, truth: Truth) -> Call {
        Call {
            api: Api::Glsl,
            args: Args {
                incident: i,
                normal: n,
                eta,
            },
            got: Got::Nothing,
            truth,
            precision: Precision::F64,
            digits: Digits::all(17),
            path: None,
            point: None,
            etap: None,
        }
    }

    fn codes(call: &Call) -> Vec<Vec<Code>> {
        let tolerance = Tolerance::new(&call.digits, f64::EPSILON);
        readings(call, &tolerance)
            .into_iter()
            .map(|r| r.codes)
            .collect()
    }

    #[test]
    fn a_reversed_incident_or_a_wrong_normal_until_travel_tells() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        let call = glsl(-d, DVec3::Y, 1.0 / 1.5, Truth::default());
        assert_eq!(
            codes(&call),
            [vec![Code::NormalNotFacing], vec![Code::IncidentReversed]]
        );
        let known = Truth {
            travel: Some(d),
            ..Truth::default()
        };
        let call = glsl(-d, DVec3::Y, 1.0 / 1.5, known);
        assert_eq!(codes(&call), [vec![Code::IncidentReversed]]);
    }

    #[test]
    fn eta_is_checked_only_against_from_and_to() {
        let d = DVec3::new(0.6, -0.8, 0.0);
        assert_eq!(codes(&glsl(d, DVec3::Y, 1.5, Truth::default())), [vec![]]);
        let truth = Truth {
            from_to: Some((1.0, 1.5)),
            ..Truth::default()
        };
        assert_eq!(
            codes(&glsl(d, DVec3::Y, 1.5, truth)),
            [vec![Code::EtaInverted]]
        );
        let long = glsl(d * 2.0, DVec3::Y, 1.5, truth);
        assert_eq!(codes(&long), [vec![Code::EtaInverted, Code::NotUnitInput]]);
        let unrelated = glsl(d, DVec3::Y, 1.2, truth);
        assert!(codes(&unrelated).is_empty());
    }
}
