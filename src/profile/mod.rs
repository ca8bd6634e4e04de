//! Wheel and rail profiles: analytic definitions (S1002, UIC60) and sampled profiles read
//! from files, with their heights, slopes and curvatures.

pub mod read;
pub mod spline;

/// Whether a profile describes a wheel or a rail; decides its side frame (see the crate docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ProfileKind {
    /// Wheel: lateral `s` from the taping line (+ field side), vertical `F` = radius increase
    /// (+ towards the flange tip).
    Wheel,
    /// Rail: lateral coordinate (+ field side), vertical = height (+ up).
    Rail,
}

impl std::fmt::Display for ProfileKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            ProfileKind::Wheel => "wheel",
            ProfileKind::Rail => "rail",
        })
    }
}
