//! The 8-neighbourhood of a cell (000 §5.2.4.9 ※1 "８連結"): one table of the eight offsets,
//! and the orthogonal-first order the global planner and the escape from the margin step in.

/// The 8-neighbour offsets `(dx, dy)`, counter-clockwise from +x: E, NE, N, NW, W, SW, S, SE.
/// The potential field assigns a finalized cell's neighbours in this order, so ties in `G`
/// are broken by it.
pub const NEIGHBOURS: [(i64, i64); 8] = [
    (1, 0),
    (1, 1),
    (0, 1),
    (-1, 1),
    (-1, 0),
    (-1, -1),
    (0, -1),
    (1, -1),
];

/// The same eight, orthogonal moves first: E, N, W, S, then the diagonals NE, NW, SW, SE (the
/// even entries of [`NEIGHBOURS`], then the odd ones). Diagonal `4 + k` lies between
/// orthogonals `k` and `(k + 1) % 4`. A* and [`super::escape_route`] expand in this order.
pub const ORTHOGONAL_FIRST: [(i64, i64); 8] = {
    let mut moves = [(0, 0); 8];
    let mut k = 0;
    while k < 4 {
        moves[k] = NEIGHBOURS[2 * k];
        moves[4 + k] = NEIGHBOURS[2 * k + 1];
        k += 1;
    }
    moves
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orthogonal_first_is_east_north_west_south_then_the_diagonals_between() {
        assert_eq!(
            ORTHOGONAL_FIRST,
            [
                (1, 0),
                (0, 1),
                (-1, 0),
                (0, -1),
                (1, 1),
                (-1, 1),
                (-1, -1),
                (1, -1)
            ]
        );
        for k in 0..4 {
            let (a, b) = (ORTHOGONAL_FIRST[k], ORTHOGONAL_FIRST[(k + 1) % 4]);
            assert_eq!(ORTHOGONAL_FIRST[4 + k], (a.0 + b.0, a.1 + b.1));
        }
    }
}
