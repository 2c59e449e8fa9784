//! A tile's premultiplied RGBA composited on white into the PNG's rows: gray for a plate,
//! RGB for an image with a coloured pixel.

use super::Channels;

/// Rows converted and handed to the encoder at once.
pub(super) const ROWS_AT_ONCE: usize = 16;

/// Premultiplied RGBA `src` composited on white into `dst`, as gray or RGB; `false` when a
/// pixel is not gray and gray was asked for.
pub(super) fn convert(src: &[u8], dst: &mut [u8], channels: Channels) -> bool {
    if channels == Channels::Gray && opaque_gray(src, dst) {
        return true;
    }
    // Over white: c + (1 − α)·255; a premultiplied channel never exceeds α.
    let over_white = |p: &[u8], k: usize| p[k].saturating_add(255 - p[3]);
    match channels {
        Channels::Gray => {
            let mut colour = 0u8;
            for (p, o) in src.chunks_exact(4).zip(dst.iter_mut()) {
                let (r, g, b) = (over_white(p, 0), over_white(p, 1), over_white(p, 2));
                colour |= (r ^ g) | (g ^ b);
                *o = r;
            }
            colour == 0
        }
        Channels::Rgb => {
            for (p, o) in src.chunks_exact(4).zip(dst.chunks_exact_mut(3)) {
                for (k, c) in o.iter_mut().enumerate() {
                    *c = over_white(p, k);
                }
            }
            true
        }
    }
}

/// The fast path of a plate, which paints its white sheet first: every pixel opaque and
/// gray, its red channel is its gray. `false` (and `dst` to be rewritten) otherwise.
fn opaque_gray(src: &[u8], dst: &mut [u8]) -> bool {
    // Whole words, no early exit: the loop vectorises.
    let mut odd = 0u32;
    for (p, o) in src.chunks_exact(4).zip(dst.iter_mut()) {
        let v = <[u8; 4]>::try_from(p).map_or(0, u32::from_le_bytes);
        odd |= ((v >> 24) ^ 0xff) | ((v ^ (v >> 8)) & 0xffff);
        *o = v as u8;
    }
    odd == 0
}
