//! The keyway of a hub (ГОСТ 23360-78, prismatic keys): by the shaft's diameter d, the
//! key's width b and height h and the keyway's depth t₂ in the hub; the drawing gives the
//! hub's b with its tolerance (JS9, the normal connection) and d + t₂ with its upper
//! deviation.

/// A hub's keyway, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Keyway {
    /// The key's (and the keyway's) width b.
    pub b: f64,
    /// The key's height h.
    pub h: f64,
    /// The keyway's depth in the hub t₂.
    pub t2: f64,
}

/// ГОСТ 23360-78, table 1: the shaft's diameter over … up to (mm), b, h, t₂ (mm).
const TABLE: [(f64, f64, f64, f64, f64); 26] = [
    (6.0, 8.0, 2.0, 2.0, 1.0),
    (8.0, 10.0, 3.0, 3.0, 1.4),
    (10.0, 12.0, 4.0, 4.0, 1.8),
    (12.0, 17.0, 5.0, 5.0, 2.3),
    (17.0, 22.0, 6.0, 6.0, 2.8),
    (22.0, 30.0, 8.0, 7.0, 3.3),
    (30.0, 38.0, 10.0, 8.0, 3.3),
    (38.0, 44.0, 12.0, 8.0, 3.3),
    (44.0, 50.0, 14.0, 9.0, 3.8),
    (50.0, 58.0, 16.0, 10.0, 4.3),
    (58.0, 65.0, 18.0, 11.0, 4.4),
    (65.0, 75.0, 20.0, 12.0, 4.9),
    (75.0, 85.0, 22.0, 14.0, 5.4),
    (85.0, 95.0, 25.0, 14.0, 5.4),
    (95.0, 110.0, 28.0, 16.0, 6.4),
    (110.0, 130.0, 32.0, 18.0, 7.4),
    (130.0, 150.0, 36.0, 20.0, 8.4),
    (150.0, 170.0, 40.0, 22.0, 9.4),
    (170.0, 200.0, 45.0, 25.0, 10.4),
    (200.0, 230.0, 50.0, 28.0, 11.4),
    (230.0, 260.0, 56.0, 32.0, 12.4),
    (260.0, 290.0, 63.0, 32.0, 12.4),
    (290.0, 330.0, 70.0, 36.0, 14.4),
    (330.0, 380.0, 80.0, 40.0, 15.4),
    (380.0, 440.0, 90.0, 45.0, 17.4),
    (440.0, 500.0, 100.0, 50.0, 19.5),
];

impl Keyway {
    /// The keyway of a hub on a shaft of diameter `d` (m); `None` outside the standard's
    /// 6 … 500 mm.
    pub fn for_shaft(d: f64) -> Option<Self> {
        let mm = d * 1e3;
        TABLE
            .iter()
            .find(|r| mm > r.0 && mm <= r.1)
            .map(|&(_, _, b, h, t2)| Keyway {
                b: b * 1e-3,
                h: h * 1e-3,
                t2: t2 * 1e-3,
            })
    }

    /// The upper deviation of t₂ and of d + t₂, m (ГОСТ 23360-78, table 1 note: by the
    /// key's height, +0,1 up to 6 mm, +0,2 up to 18 mm, +0,3 above).
    pub fn depth_deviation(&self) -> f64 {
        let h = self.h * 1e3;
        let dev = if h <= 6.0 {
            0.1
        } else if h <= 18.0 {
            0.2
        } else {
            0.3
        };
        dev * 1e-3
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The standard's rows at their bounds: the shaper's hub (d₁ = 172 mm) takes 45 × 25
    /// with t₂ = 10,4 mm; the V engine's (76 mm) 22 × 14 with t₂ = 5,4; 170 mm belongs to
    /// the row up to 170; outside 6 … 500 mm there is none.
    #[test]
    fn the_keyway_is_the_standards_row_of_the_shaft() {
        let mm = |k: Keyway| [k.b, k.h, k.t2, k.depth_deviation()].map(|x| x * 1e3);
        let close = |a: [f64; 4], b: [f64; 4]| a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-12);
        let k = Keyway::for_shaft(0.172).expect("172 mm");
        assert!(close(mm(k), [45.0, 25.0, 10.4, 0.3]), "{k:?}");
        let v = Keyway::for_shaft(0.076).expect("76 mm");
        assert!(close(mm(v), [22.0, 14.0, 5.4, 0.2]), "{v:?}");
        let at_bound = Keyway::for_shaft(0.170).expect("170 mm");
        assert!(close(mm(at_bound), [40.0, 22.0, 9.4, 0.3]), "{at_bound:?}");
        assert_eq!(Keyway::for_shaft(0.006), None);
        assert_eq!(Keyway::for_shaft(0.501), None);
        // The rows run on without a gap.
        assert!(TABLE.windows(2).all(|w| w[0].1 == w[1].0));
    }
}
