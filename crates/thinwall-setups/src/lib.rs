//! Set-ups of a part (issue 37), below the planners that use them (the
//! plan and the operations): which ups to machine from, proposed on height
//! maps of the part's mesh and checked on exact removals
//! ([`proposal`], [`choice`], [`heights`]), and each set-up taken in turn:
//! its stock what the set-ups before it left, what none reaches the
//! residue ([`turn`]).

pub mod choice;
pub mod heights;
pub mod proposal;
pub mod turn;

pub use proposal::{propose, setups, Proposal};
pub use turn::{in_turn, residue, Judged, Residue};
