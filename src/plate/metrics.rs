//! Glyph metrics of the face every plate text is drawn with: the SVG sets `font-style="italic"`,
//! which the bundled font database resolves to DejaVu Sans Oblique. Advances come from its
//! `hmtx` table, ink boxes from the glyph headers in `glyf`, characters map to glyphs through
//! the `cmap` format 4 subtable — the same numbers the renderer lays the text out with
//! (kerning aside, which the label boxes' padding covers).

use std::sync::OnceLock;

/// A glyph's metrics in em (y up, from the pen position on the baseline).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Glyph {
    /// Advance width.
    pub advance: f64,
    /// Ink box `(x_min, y_min, x_max, y_max)`; `None` for a blank glyph (space).
    pub ink: Option<(f64, f64, f64, f64)>,
}

/// Offsets of the tables the metrics are read from.
struct Face {
    data: &'static [u8],
    units: f64,
    long_loca: bool,
    metrics: usize,
    hmtx: usize,
    loca: usize,
    glyf: usize,
    /// The format 4 subtable of `cmap` (Unicode BMP).
    cmap4: usize,
}

fn u16_at(d: &[u8], at: usize) -> u16 {
    d.get(at..at + 2)
        .map_or(0, |b| u16::from_be_bytes([b[0], b[1]]))
}

fn i16_at(d: &[u8], at: usize) -> i16 {
    u16_at(d, at) as i16
}

fn u32_at(d: &[u8], at: usize) -> u32 {
    d.get(at..at + 4)
        .map_or(0, |b| u32::from_be_bytes([b[0], b[1], b[2], b[3]]))
}

impl Face {
    fn parse(data: &'static [u8]) -> Face {
        let tables = u16_at(data, 4) as usize;
        let table = |tag: &[u8; 4]| {
            (0..tables)
                .map(|k| 12 + 16 * k)
                .find(|&rec| data.get(rec..rec + 4) == Some(&tag[..]))
                .map_or(0, |rec| u32_at(data, rec + 8) as usize)
        };
        let (head, hhea, cmap) = (table(b"head"), table(b"hhea"), table(b"cmap"));
        let cmap4 = (0..u16_at(data, cmap + 2) as usize)
            .map(|k| cmap + 4 + 8 * k)
            .filter(|&rec| u16_at(data, rec) == 3 && u16_at(data, rec + 2) == 1)
            .map(|rec| cmap + u32_at(data, rec + 4) as usize)
            .find(|&sub| u16_at(data, sub) == 4)
            .unwrap_or(0);
        Face {
            data,
            units: f64::from(u16_at(data, head + 18).max(1)),
            long_loca: i16_at(data, head + 50) == 1,
            metrics: (u16_at(data, hhea + 34) as usize).max(1),
            hmtx: table(b"hmtx"),
            loca: table(b"loca"),
            glyf: table(b"glyf"),
            cmap4,
        }
    }

    /// The glyph of `c` (0, the missing glyph, when the face has none).
    fn glyph_id(&self, c: char) -> usize {
        let (d, sub) = (self.data, self.cmap4);
        let code = match u16::try_from(u32::from(c)) {
            Ok(code) if sub != 0 => code,
            _ => return 0,
        };
        let segs = (u16_at(d, sub + 6) / 2) as usize;
        let ends = sub + 14;
        let starts = ends + 2 * segs + 2;
        let deltas = starts + 2 * segs;
        let ranges = deltas + 2 * segs;
        let Some(k) = (0..segs).find(|&k| u16_at(d, ends + 2 * k) >= code) else {
            return 0;
        };
        let start = u16_at(d, starts + 2 * k);
        if start > code {
            return 0;
        }
        let delta = u16_at(d, deltas + 2 * k);
        let range = u16_at(d, ranges + 2 * k) as usize;
        if range == 0 {
            return code.wrapping_add(delta) as usize;
        }
        let at = ranges + 2 * k + range + 2 * (code - start) as usize;
        match u16_at(d, at) {
            0 => 0,
            g => g.wrapping_add(delta) as usize,
        }
    }

    fn glyph_offset(&self, id: usize) -> usize {
        if self.long_loca {
            u32_at(self.data, self.loca + 4 * id) as usize
        } else {
            2 * u16_at(self.data, self.loca + 2 * id) as usize
        }
    }

    fn glyph(&self, c: char) -> Glyph {
        let id = self.glyph_id(c);
        let d = self.data;
        let advance = u16_at(d, self.hmtx + 4 * id.min(self.metrics - 1));
        let (start, end) = (self.glyph_offset(id), self.glyph_offset(id + 1));
        let k = 1.0 / self.units;
        let ink = (end > start).then(|| {
            let at = self.glyf + start;
            let v = |o: usize| f64::from(i16_at(d, at + o)) * k;
            (v(2), v(4), v(6), v(8))
        });
        Glyph {
            advance: f64::from(advance) * k,
            ink,
        }
    }
}

fn face() -> &'static Face {
    static FACE: OnceLock<Face> = OnceLock::new();
    FACE.get_or_init(|| Face::parse(dejavu::sans::oblique()))
}

/// The metrics of `c` in the plates' face, em.
pub(crate) fn glyph(c: char) -> Glyph {
    face().glyph(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn metrics_are_read_from_the_face() {
        // DejaVu Sans: 2048 units per em, digits 1303 units wide, capitals 1493 units high.
        let three = glyph('3');
        assert!((three.advance - 1303.0 / 2048.0).abs() < 1e-9);
        let h = glyph('H').ink.expect("ink");
        assert!((h.3 - 1493.0 / 2048.0).abs() < 1e-9, "{h:?}");
        assert_eq!(glyph(' ').ink, None);
        assert!(glyph(' ').advance > 0.2);
        // Cyrillic, Greek and the prime are in the face; a private-use character is not.
        for c in ['ж', 'π', 'ω', '′', '≡'] {
            assert!(glyph(c).ink.is_some(), "{c}");
        }
        assert_eq!(face().glyph_id('\u{E000}'), 0);
    }
}
