//! Global path planning: A* on the 8-connected grid (SPEC §5 "GlobalPathPlanning").
