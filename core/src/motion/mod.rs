//! The robot's motion: differential-drive kinematics and the physics that replaces OpenHRP3
//! (SPEC §4, §5).
