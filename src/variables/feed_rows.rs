//! The rows of one lubricated joint's oil feed ([`feed_rows!`]), the same for the three joints of
//! [`super::joints`]: the feed's kind, the body it sits in, its position and size, and the flow
//! the supply pressure drives through it.

/// Number of rows of each joint's feed ([`feed_rows`]).
pub(super) const FEED_ROWS: usize = 6;

/// Every row of a joint's feed. Arguments: the variable-name prefix, its name starting a
/// description, the bodies whose axes the feed's position is measured from (the shell's, the
/// journal's), and the 6 value references in the order of the rows.
macro_rules! feed_rows {
    (
        $prefix:literal,
        $label:literal,
        $axes:literal,
        [
            $feed:ident,
            $location:ident,
            $position:ident,
            $diameter:ident,
            $groove_length:ident,
            $flow:ident $(,)?
        ]
    ) => {
        [
            Variable::enumeration(
                Vr::$feed,
                concat!($prefix, ".feed"),
                1,
                FEED,
                concat!(
                    $label,
                    ": the lubricated joint's oil feed, through which oil.supplyPressure drives a flow through the clearance (",
                    $prefix,
                    ".feedFlow) beside the film's own"
                ),
            ),
            Variable::enumeration(
                Vr::$location,
                concat!($prefix, ".feedLocation"),
                1,
                FEED_LOCATION,
                concat!($label, ": the body the feed hole or axial groove sits in"),
            ),
            Variable::parameter(
                Vr::$position,
                concat!($prefix, ".feedPosition"),
                0.0,
                -7.0,
                7.0,
                "rad",
                concat!(
                    $label,
                    ": angle of the feed hole or axial groove from its body's axis, counter-clockwise (",
                    $axes,
                    ")"
                ),
            ),
            Variable::parameter(
                Vr::$diameter,
                concat!($prefix, ".feedDiameter"),
                4e-3,
                1e-5,
                1.0,
                "m",
                concat!(
                    $label,
                    ": the feed hole's diameter or the groove's width (at most half of ",
                    $prefix,
                    ".bearingLength)"
                ),
            ),
            Variable::parameter(
                Vr::$groove_length,
                concat!($prefix, ".feedGrooveLength"),
                0.8,
                0.05,
                0.94,
                "1",
                concat!(
                    $label,
                    ": the axial groove's length as a fraction of ",
                    $prefix,
                    ".bearingLength, centred (with half its width, below 0.95)"
                ),
            ),
            Variable::output(
                Vr::$flow,
                concat!($prefix, ".feedFlow"),
                "m3/s",
                concat!(
                    $label,
                    ": the flow oil.supplyPressure drives from the feed through the clearance, c^3 p_s S h_f^3/(12 mu) (part of ",
                    $prefix,
                    ".oilFlow); 0 without a feed"
                ),
            ),
        ]
    };
}

pub(super) use feed_rows;
