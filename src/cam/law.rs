//! The follower's motion laws of one phase, in closed form: the normalised displacement
//! f(u), u = (φ − φ₀)/Φ ∈ [0, 1], and its derivatives f′, f″ with respect to u. A rise of
//! stroke h over Φ is S = h·f(u), S′ = h·f′(u)/Φ, S″ = h·f″(u)/Φ²; a return is h − S.

use std::f64::consts::PI;

/// A motion law of a rise or a return (lecture 14 of seed 001; the textbook gives it by its
/// acceleration analogue d²S/dφ²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Law {
    /// Uniform (constant velocity): S linear; the velocity jumps at both ends, so the
    /// acceleration is infinite there — rigid shocks (жёсткий удар).
    Uniform,
    /// Constant acceleration "+ −" (parabolic): d²S/dφ² = +a₁ over the first `ratio` of the
    /// phase and −a₂ over the rest, a₁·ratio = a₂·(1 − ratio); soft shocks at 0, ratio, 1.
    ConstantAcceleration {
        /// The share of the phase with positive acceleration, 0 < ratio < 1 (½: symmetric).
        ratio: f64,
    },
    /// Cosine (harmonic): S = h(1 − cos πu)/2; soft shocks at the ends.
    Cosine,
    /// Sine (cycloidal): S = h(u − sin 2πu/2π); no shock.
    Sine,
    /// Trapezoidal acceleration: ramps over the first, middle and last eighths (jerk finite),
    /// constant acceleration between; no shock.
    Trapezoidal,
    /// The 3-4-5 polynomial S = h(10u³ − 15u⁴ + 6u⁵); no shock.
    Polynomial345,
    /// Linear with blends (seed 001 L1590, fig. 67): uniform motion over the middle of the
    /// phase, rounded at both ends by parabolic blends of constant acceleration over the
    /// share `blend` of the phase each; the acceleration is finite (soft shocks at 0,
    /// blend, 1 − blend, 1) and grows as the blends shrink.
    LinearBlended {
        /// The share of the phase each blend takes, 0 < blend ≤ ½ (½: the "+ −" law).
        blend: f64,
    },
}

/// The shock a law gives at the ends of its phase (and inside it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shock {
    /// The velocity jumps: infinite acceleration (жёсткий удар).
    Rigid,
    /// The acceleration jumps (мягкий удар).
    Soft,
    /// Velocity and acceleration continuous.
    None,
}

/// The knots of the trapezoidal law: u and the normalised acceleration there (× A).
const TRAPEZOID: [(f64, f64); 6] = [
    (0.0, 0.0),
    (0.125, 1.0),
    (0.375, 1.0),
    (0.625, -1.0),
    (0.875, -1.0),
    (1.0, 0.0),
];

impl Law {
    /// The law's name as scenes write it.
    pub fn key(self) -> &'static str {
        match self {
            Law::Uniform => "uniform",
            Law::ConstantAcceleration { .. } => "constant-acceleration",
            Law::Cosine => "cosine",
            Law::Sine => "sine",
            Law::Trapezoidal => "trapezoidal",
            Law::Polynomial345 => "polynomial-345",
            Law::LinearBlended { .. } => "linear-blended",
        }
    }

    /// The shock the law gives.
    pub fn shock(self) -> Shock {
        match self {
            Law::Uniform => Shock::Rigid,
            Law::ConstantAcceleration { .. } | Law::Cosine | Law::LinearBlended { .. } => {
                Shock::Soft
            }
            Law::Sine | Law::Trapezoidal | Law::Polynomial345 => Shock::None,
        }
    }

    /// Where inside the phase the acceleration analogue jumps (u), besides the ends.
    pub fn breaks(self) -> Vec<f64> {
        match self {
            Law::ConstantAcceleration { ratio } => vec![ratio],
            Law::LinearBlended { blend } if blend < 0.5 => vec![blend, 1.0 - blend],
            Law::LinearBlended { .. } => vec![0.5],
            _ => Vec::new(),
        }
    }

    /// Where inside the phase the given acceleration analogue's diagram breaks: its jumps
    /// ([`Law::breaks`]) and its corners, where its slope jumps (the trapezoidal law's
    /// knots). The diagram is smooth between them, so a division point of the graphical
    /// integration belongs on each.
    pub fn knots(self) -> Vec<f64> {
        match self {
            Law::Trapezoidal => TRAPEZOID[1..TRAPEZOID.len() - 1]
                .iter()
                .map(|&(u, _)| u)
                .collect(),
            _ => self.breaks(),
        }
    }

    /// (f, f′, f″) at u ∈ [0, 1]; at a break, `after` picks the piece that follows it.
    pub fn eval(self, u: f64, after: bool) -> (f64, f64, f64) {
        match self {
            Law::Uniform => (u, 1.0, 0.0),
            Law::ConstantAcceleration { ratio: k } => {
                if u < k || (u == k && !after) {
                    (u * u / k, 2.0 * u / k, 2.0 / k)
                } else {
                    let w = 1.0 - u;
                    let m = 1.0 - k;
                    (1.0 - w * w / m, 2.0 * w / m, -2.0 / m)
                }
            }
            Law::Cosine => (
                (1.0 - (PI * u).cos()) / 2.0,
                PI / 2.0 * (PI * u).sin(),
                PI * PI / 2.0 * (PI * u).cos(),
            ),
            Law::Sine => {
                let t = 2.0 * PI * u;
                (u - t.sin() / (2.0 * PI), 1.0 - t.cos(), 2.0 * PI * t.sin())
            }
            Law::Trapezoidal => trapezoid(u),
            Law::LinearBlended { blend: b } => {
                // The middle's velocity v: S = v(1 − 2b) + 2·vb/2 = v(1 − b) = 1.
                let v = 1.0 / (1.0 - b);
                if u < b || (u == b && !after) {
                    (v * u * u / (2.0 * b), v * u / b, v / b)
                } else if u < 1.0 - b || (u == 1.0 - b && !after) {
                    (v * (u - b / 2.0), v, 0.0)
                } else {
                    let w = 1.0 - u;
                    (1.0 - v * w * w / (2.0 * b), v * w / b, -v / b)
                }
            }
            Law::Polynomial345 => {
                let (u2, u3) = (u * u, u * u * u);
                (
                    u3 * (10.0 - 15.0 * u + 6.0 * u2),
                    30.0 * u2 * (1.0 - 2.0 * u + u2),
                    60.0 * u * (1.0 - 3.0 * u + 2.0 * u2),
                )
            }
        }
    }
}

/// The trapezoidal law: the acceleration is linear on each piece between the knots, so
/// velocity and displacement are exact quadratics and cubics; the amplitude makes f(1) = 1.
fn trapezoid(u: f64) -> (f64, f64, f64) {
    // Integrate the unit-amplitude shape piece by piece up to u (exactly), then scale.
    let integrate = |upto: f64| {
        let (mut v, mut s) = (0.0, 0.0);
        let mut acc = 0.0;
        for w in TRAPEZOID.windows(2) {
            let ((u0, a0), (u1, a1)) = (w[0], w[1]);
            if upto <= u0 {
                break;
            }
            let t = upto.min(u1) - u0;
            let slope = (a1 - a0) / (u1 - u0);
            s += v * t + a0 * t * t / 2.0 + slope * t * t * t / 6.0;
            v += a0 * t + slope * t * t / 2.0;
            acc = a0 + slope * t;
        }
        (s, v, acc)
    };
    let amplitude = 1.0 / integrate(1.0).0;
    let (s, v, a) = integrate(u.clamp(0.0, 1.0));
    (s * amplitude, v * amplitude, a * amplitude)
}
