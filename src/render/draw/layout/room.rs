//! How much room a picture printed small gives its arrows, its labels and its system.

/// The room of a picture whose labels take `grow` times their room at 13 px: printed
/// small, its arrows are drawn `reach` times as long, so that they print about 18 pt long
/// at least (a label of 7 pt takes 13 px × `grow`, so 44 px × 0.75 `grow` prints so), and
/// the margin round the system grows by what the longer arrows and larger labels take
/// while the system shrinks by as much (to two fifths of its size at most): the picture
/// keeps its size on the page.
pub(super) struct Room {
    /// How many times its length at 13 px every arrow is drawn.
    pub(super) reach: f64,
    /// The margin round the system (px).
    pub(super) margin: f64,
    /// The system's largest extent (px).
    pub(super) content: f64,
}

impl Room {
    /// The room for a system `content` px across whose labels take `grow` times their
    /// room.
    pub(super) fn of(content: f64, grow: f64) -> Room {
        let reach = (0.75 * grow).max(1.0);
        let extra = (super::super::strokes::arrow_length(0) * (reach - 1.0)
            + 16.0 * (grow - 1.0).max(0.0))
        .min(0.3 * content);
        Room {
            reach,
            margin: super::super::fit::MARGIN + extra,
            content: content - 2.0 * extra,
        }
    }
}
