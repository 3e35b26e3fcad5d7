//! The side of a surface a ray arrives from: the one word the tracer, the log diagnosis and the
//! failure map share for "entering" and "leaving".

/// The side of a surface a ray arrives from, relative to the object the surface bounds: a ray
/// from outside enters the object, one from inside leaves it. In JSON (the `trace` command's
/// hits) the sides are written `entering` and `leaving`, the words of a log's `entering` field.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub enum Side {
    /// From outside: the ray enters the object, and the outward normal faces it.
    #[cfg_attr(feature = "serde", serde(rename = "entering"))]
    Outside,
    /// From inside: the ray leaves the object, and the outward normal points along it (the
    /// kernel turns it to face the ray). Where only a normal tells, the normal's far side.
    #[cfg_attr(feature = "serde", serde(rename = "leaving"))]
    Inside,
}

impl Side {
    /// The side of a ray that is entering the object (`true`) or leaving it.
    #[must_use]
    pub const fn of_entering(entering: bool) -> Self {
        if entering {
            Self::Outside
        } else {
            Self::Inside
        }
    }

    /// Whether a ray from this side enters the object.
    #[must_use]
    pub const fn is_entering(self) -> bool {
        matches!(self, Self::Outside)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entering_is_from_outside_and_leaving_from_inside() {
        assert_eq!(Side::of_entering(true), Side::Outside);
        assert_eq!(Side::of_entering(false), Side::Inside);
        for side in [Side::Outside, Side::Inside] {
            assert_eq!(Side::of_entering(side.is_entering()), side);
        }
    }
}
