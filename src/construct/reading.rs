//! A reading: a segment measured off a figure ([`super::Recorder::measure`]) with the value it
//! gave — where on the drawing a graphical result was read.

use crate::geom::DVec2;

/// One measurement taken off a figure: the segment `from`–`to` (figure mm, y up) and the
/// physical value it was read as (its length under the drafting model times μ, SI).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reading {
    /// One end of the segment measured, figure mm.
    pub from: DVec2,
    /// The other end, figure mm.
    pub to: DVec2,
    /// The length as read, mm (the drafting model's reading of `|to − from|`).
    pub read_mm: f64,
    /// The physical value read: `read_mm × μ` of the figure, SI.
    pub value: f64,
    /// The group of the steps drawn when it was taken (a position's number; 0 when unused):
    /// a figure keeping only some groups keeps only their readings.
    pub group: u32,
}

impl Reading {
    /// The same reading with both ends through `m` (an isometry of the figure).
    pub fn moved(&self, m: impl Fn(DVec2) -> DVec2) -> Reading {
        Reading {
            from: m(self.from),
            to: m(self.to),
            ..*self
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::Figure;
    use crate::scale::{Quantity, Scale};

    /// A figure's readings go through the same map as its steps (translated, mirrored),
    /// follow it when joined and keep to its groups, their values unchanged.
    #[test]
    fn readings_move_with_their_figure() {
        let r = Reading {
            from: DVec2::new(1.0, 2.0),
            to: DVec2::new(4.0, 6.0),
            read_mm: 5.0,
            value: 0.005,
            group: 2,
        };
        let f = Figure {
            title: "t".into(),
            scale: Scale::new(0.001, Quantity::Length).expect("μ"),
            steps: Vec::new(),
            readings: vec![r],
        };
        let m = f.mirrored_x().readings[0];
        assert_eq!(
            (m.from, m.to),
            (DVec2::new(-1.0, 2.0), DVec2::new(-4.0, 6.0))
        );
        assert_eq!((m.read_mm, m.value, m.group), (5.0, 0.005, 2));
        let d = DVec2::new(10.0, -5.0);
        let j = f.clone().joined(f.translated(d));
        assert_eq!(j.readings.len(), 2);
        assert_eq!(
            (j.readings[1].from, j.readings[1].to),
            (r.from + d, r.to + d)
        );
        assert!(f.only_groups(&[1]).readings.is_empty());
        assert_eq!(f.only_groups(&[2]).readings, f.readings);
    }
}
