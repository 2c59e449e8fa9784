//! A dimension's text beside its line, clear of the lines of its view: over the middle of the
//! dimension line when that is free (ГОСТ 2.307), else slid along the line, under it, or past
//! its arrows on the line's extension; where none of these is free, on the shelf of a leader
//! from the middle of the line (ГОСТ 2.307: a line with no room for its number) — never
//! struck through by a line of its own view.

use super::away::NEARER_MM;
use super::clip::{clipped_area, clipped_length, own_distance};
use super::leader::{self, Leader};
use super::place::written;
use super::{shape_box, Outline, Request, Shape, LABEL_HEIGHT_MM};
use crate::construct::{Item, Names};
use crate::geom::DVec2;
use crate::plate::dimension::{dimension_text, TextSpot};
use crate::plate::path::Map;
use crate::plate::text::{measure, Placed};
use crate::plate::{Plate, Rect};

/// Step of the slide along the dimension line, mm.
const SLIDE_MM: f64 = 1.5;
/// Room kept at each end of the dimension line for its arrowhead, mm.
const ARROW_ROOM_MM: f64 = 3.0;
/// Slides tried past each arrow, on the line's extension.
const PAST_STEPS: usize = 8;
/// Slides tried each way between the arrows: a text slid further than this from the middle
/// of its line is no better placed (a dimension line of any length asks a bounded search).
const MOST_SLIDES: usize = 200;
/// Clearance a text keeps from a line while placing, mm.
const CLEAR_MM: f64 = 0.3;
/// Clearance a text keeps from its own dimension's extension lines, mm: a text between
/// them closer than this reads as crowded against them (ГОСТ 2.307 then writes it past an
/// arrow or on a leader); less than the text's gap from its dimension line.
const OWN_CLEAR_MM: f64 = 0.8;

/// Cost of a place over another text (a caption, a table, another dimension's text), as mm
/// of line struck.
const OVER_TEXT: f64 = 100.0;
/// Cost of a place nearer another line of the view than its own dimension's (a reader takes
/// the text for that line's), as mm of line struck, and per mm it is nearer.
const WRONG_LINE: f64 = 50.0;
const WRONG_LINE_MM: f64 = 10.0;

/// The dimension `(from, to, offset)`'s text `text` placed (see the module documentation):
/// the first place, in order of preference, whose box meets no line of `lines` (the view's
/// outlines) and no text of `texts`, and is no nearer another line than its own dimension's
/// (`own`, its outlines among `lines`); when none is, the least struck — or, where that one is
/// struck through by a line or covers a text, the least costly leader whose text is clear
/// ([`on_leader`]).
pub(super) fn placed(
    map: Map,
    dim: (DVec2, DVec2, f64),
    text: &str,
    (lines, own): (&[Outline], &[Outline]),
    texts: &[Rect],
) -> Option<(Placed, Option<Leader>)> {
    let first = dimension_text(map, dim, text, TextSpot::MIDDLE)?;
    let width = first.own_box().width();
    let (from, to, offset) = dim;
    let length = map.dir(to - from).length();
    let middle = map.pt((from + to) * 0.5 + (to - from).normalize_or_zero().perp() * offset);
    let extensions = extension_lines(map, dim);
    // A text written past an arrow stands over the line run on under it.
    let with_line = |p: Placed, spot: TextSpot| {
        let line = run_on(&p, spot, (middle, length), width);
        Some((p, line))
    };
    let mut best: Option<(Placed, f64, TextSpot)> = None;
    for (rank, spot) in spots(length, width).into_iter().enumerate() {
        let Some(p) = dimension_text(map, dim, text, spot) else {
            continue;
        };
        let over = over_texts(texts, &p.bounds().inflate(CLEAR_MM));
        let ink = struck(&p, lines, CLEAR_MM)
            + struck(&p, &extensions, OWN_CLEAR_MM)
            + over
            + wrong_line(&p.bounds(), lines, own);
        if ink == 0.0 {
            return with_line(p, spot);
        }
        let cost = ink + rank as f64 * 1e-3;
        if best.as_ref().is_none_or(|b| cost < b.1) {
            best = Some((p, cost, spot));
        }
    }
    let (p, _, spot) = best?;
    // Within the clearance of a line is kept; through a line or a text, a leader is taken.
    let through = struck(&p, lines, 0.0) + over_texts(texts, &p.bounds()) > 0.0;
    match through
        .then(|| on_leader(map, dim, text, lines, texts))
        .flatten()
    {
        Some((q, l)) => Some((q, Some(l))),
        None => with_line(p, spot),
    }
}

/// The dimension line run on past its arrow under a text written on its extension (ГОСТ
/// 2.307: the number stands over the dimension line's continuation, not in the air beside
/// the axis past it): drawn as the shelf of a leader from the arrow's tip, along the line to
/// [`RUN_ON_PAST_MM`] beyond the text `p` written at `spot` (`width` mm long) beside the
/// line whose middle is `middle` and which is `length` long, sheet mm; `None` for a text
/// between the arrows.
fn run_on(
    p: &Placed,
    spot: TextSpot,
    (middle, length): (DVec2, f64),
    width: f64,
) -> Option<Leader> {
    let reach = 0.5 * length;
    if spot.along.abs() <= reach {
        return None;
    }
    let read = DVec2::from_angle(p.rotate.to_radians());
    let sign = spot.along.signum();
    let tip = middle + read * (sign * reach);
    let end = middle + read * (spot.along + sign * (0.5 * width + RUN_ON_PAST_MM));
    Some(Leader {
        to: tip,
        from: tip,
        dot: false,
        knee: tip,
        end,
        run_on: true,
    })
}

/// How far a dimension line run on under its text reaches past the text, mm.
const RUN_ON_PAST_MM: f64 = 1.0;

/// The extension lines of the dimension `(from, to, offset)` as drawn, run past the
/// dimension line ([`crate::plate::dimension::extension_lines`]; the outlines of the view
/// end them on it).
fn extension_lines(map: Map, (from, to, offset): (DVec2, DVec2, f64)) -> Vec<Outline> {
    crate::plate::dimension::extension_lines(from, to, offset)
        .into_iter()
        .map(|(p, q)| Outline {
            shape: Shape::Line(map.pt(p), map.pt(q)),
            main: false,
        })
        .collect()
}

/// The dimension's text written level on the shelf of a leader from the middle of its line
/// (no dot: the leader starts on the line), among the places [`leader::candidates`] tries:
/// the least costly leader ([`leader::cost`]) whose text meets no line of `lines` and no text
/// of `texts`; `None` when every one is struck or covered.
fn on_leader(
    map: Map,
    (from, to, offset): (DVec2, DVec2, f64),
    text: &str,
    lines: &[Outline],
    texts: &[Rect],
) -> Option<(Placed, Leader)> {
    let u = (to - from).try_normalize()?;
    let middle = map.pt((from + to) * 0.5 + u.perp() * offset);
    let request = Request {
        view: 0,
        steps: Vec::new(),
        names: vec![text.to_string()],
        anchor: middle,
        toward: DVec2::ZERO,
        gap: 0.0,
        within: None,
        column: None,
        names_of: Names::Point,
        own: Vec::new(),
    };
    let boxed: Vec<(Rect, &Outline)> = lines
        .iter()
        .filter_map(|o| Some((shape_box(&o.shape)?, o)))
        .collect();
    let e = measure(text, LABEL_HEIGHT_MM);
    leader::candidates(&request, e.max - e.min)
        .into_iter()
        .enumerate()
        .filter_map(|(rank, (rect, l))| {
            let p = written(text, &e, rect);
            let b = p.bounds().inflate(CLEAR_MM);
            let clear = struck(&p, lines, CLEAR_MM) + over_texts(texts, &b) == 0.0;
            let cost = leader::cost(&l, &rect, &boxed, &[], texts, &[]);
            clear.then_some((cost + rank as f64 * leader::RANK, p, l))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, p, l)| (p, l))
}

/// What a text whose box is `rect` costs for covering texts of `texts` (zero: it covers none).
fn over_texts(texts: &[Rect], rect: &Rect) -> f64 {
    texts
        .iter()
        .map(|t| t.overlap(rect))
        .filter(|&a| a > 0.0)
        .map(|a| OVER_TEXT + a)
        .sum()
}

/// What a text whose box is `rect` costs for standing nearer another line of `lines` than
/// its own dimension's lines `own` (zero when it is not, or `own` has no line).
fn wrong_line(rect: &Rect, lines: &[Outline], own: &[Outline]) -> f64 {
    let Some(mine) = own_distance(own, rect) else {
        return 0.0;
    };
    let others = lines.iter().filter(|o| !own.contains(o));
    let rival = own_distance(others, rect).unwrap_or(f64::INFINITY);
    match rival + NEARER_MM < mine {
        true => WRONG_LINE + WRONG_LINE_MM * (mine - rival),
        false => 0.0,
    }
}

/// The places tried for a text `width` mm long beside a dimension line `length` mm long, in
/// order of preference: over the line, at its middle then slid both ways while the text stays
/// between the arrows; the same under the line; then past the arrows, on the line's extension.
fn spots(length: f64, width: f64) -> Vec<TextSpot> {
    let free = 0.5 * length - ARROW_ROOM_MM - 0.5 * width;
    let mut alongs = vec![0.0];
    for k in 1..=MOST_SLIDES {
        let along = k as f64 * SLIDE_MM;
        if free.is_nan() || along > free {
            break;
        }
        alongs.extend([along, -along]);
    }
    let past = 0.5 * length + ARROW_ROOM_MM + 0.5 * width;
    let pasts = (0..PAST_STEPS).flat_map(|k| {
        let along = past + k as f64 * SLIDE_MM;
        [along, -along]
    });
    let at = |under: bool| move |&along: &f64| TextSpot { along, under };
    let mut out: Vec<TextSpot> = alongs.iter().map(at(false)).collect();
    out.extend(alongs.iter().map(at(true)));
    out.extend(pasts.flat_map(|along| [false, true].map(|under| TextSpot { along, under })));
    out
}

/// How much of `lines` the box of `text`, grown by `clear`, holds: mm of line plus mm² of
/// symbol (zero: the text is struck by none).
pub(crate) fn struck(text: &Placed, lines: &[Outline], clear: f64) -> f64 {
    let own = text.own_box().inflate(clear);
    let reach = Rect::around(text.corners()).map(|r| r.inflate(clear));
    lines
        .iter()
        .map(|o| match &o.shape {
            Shape::Line(a, b) => {
                if reach.is_some_and(|r| !r.touches(&Rect::around([*a, *b]).unwrap_or(r))) {
                    return 0.0;
                }
                clipped_length(text.to_own(*a), text.to_own(*b), &own)
            }
            Shape::Area(pts) => {
                let turned: Vec<DVec2> = pts.iter().map(|&p| text.to_own(p)).collect();
                clipped_area(&turned, &own)
            }
        })
        .sum()
}

/// Every dimension text of `plate` struck by a line of its own view: (view, text, mm of line
/// plus mm² of symbol inside the text's box as written). Empty when every text is clear.
pub fn struck_dimension_texts(plate: &Plate) -> Vec<(usize, String, f64)> {
    let laid = super::layout(plate);
    let outlines: Vec<Vec<Outline>> = plate.views.iter().map(super::view_outlines).collect();
    laid.labels
        .iter()
        .filter(|l| {
            let steps = &plate.views[l.view].figure.steps;
            l.steps.iter().any(|id| {
                steps
                    .get(id.0 as usize)
                    .is_some_and(|s| matches!(s.item, Item::Dimension { .. }))
            })
        })
        .map(|l| {
            (
                l.view,
                l.text.clone(),
                struck(&l.placed, &outlines[l.view], 0.0),
            )
        })
        .filter(|s| s.2 > 0.0)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_middle_first_then_along_the_line_then_past_its_arrows() {
        let s = spots(40.0, 6.0);
        assert_eq!(s[0], TextSpot::MIDDLE);
        // Slid over the line before it goes under it.
        let first_under = s.iter().position(|t| t.under).expect("under");
        assert!(first_under > 2 && s[first_under].along == 0.0);
        assert!(s[..first_under].iter().all(|t| !t.under));
        // Between the arrows the text keeps their room.
        let inside: Vec<&TextSpot> = s.iter().filter(|t| t.along.abs() < 20.0).collect();
        assert!(inside
            .iter()
            .all(|t| t.along.abs() + 3.0 <= 20.0 - ARROW_ROOM_MM + 1e-9));
        assert!(inside.len() > 10);
        // A line shorter than its text: the middle, then only past the arrows.
        let short = spots(2.0, 6.0);
        assert_eq!(
            short[1],
            TextSpot {
                along: 0.0,
                under: true
            }
        );
        assert!(short[2..]
            .iter()
            .all(|t| t.along.abs() >= 1.0 + ARROW_ROOM_MM + 3.0));
    }

    #[test]
    fn a_line_of_any_length_asks_a_bounded_search() {
        let most = 4 * (MOST_SLIDES * 2 + 1) + 4 * PAST_STEPS;
        for length in [1e3, 1e9, 8.0e17, f64::MAX, f64::INFINITY, f64::NAN] {
            let s = spots(length, 6.0);
            assert!(s.len() <= most, "{length}: {} places", s.len());
            assert_eq!(s[0], TextSpot::MIDDLE, "{length}");
        }
        // A long line slides its text up to the cap, both ways.
        let s = spots(1e6, 6.0);
        let far = MOST_SLIDES as f64 * SLIDE_MM;
        assert!(s.iter().any(|t| t.along == far) && s.iter().any(|t| t.along == -far));
    }

    #[test]
    fn a_line_through_the_middle_slides_the_text_clear_of_it() {
        let map = Map::figure(DVec2::ZERO);
        // A horizontal dimension 60 mm long, a line crossing its middle upright.
        let dim = (DVec2::ZERO, DVec2::new(60.0, 0.0), 0.0);
        let cross = Outline {
            shape: Shape::Line(DVec2::new(30.0, -20.0), DVec2::new(30.0, 20.0)),
            main: false,
        };
        let middle = dimension_text(map, dim, "H", TextSpot::MIDDLE).expect("text");
        assert!(struck(&middle, std::slice::from_ref(&cross), 0.0) > 1.0);
        let lines = std::slice::from_ref(&cross);
        let (p, _) = placed(map, dim, "H", (lines, &[]), &[]).expect("placed");
        assert_eq!(struck(&p, &[cross], CLEAR_MM), 0.0);
        assert!(
            (p.at.x - 30.0).abs() < 6.0,
            "kept near the middle: {:?}",
            p.at
        );
        // A caption under the line and one over it left of the middle: the text goes right.
        let captions = [
            Rect::new(DVec2::new(0.0, 0.5), DVec2::new(60.0, 6.0)),
            Rect::new(DVec2::new(0.0, -6.0), DVec2::new(30.0, -0.5)),
        ];
        let (q, _) = placed(map, dim, "H", (&[], &[]), &captions).expect("placed");
        assert!(
            captions.iter().all(|c| !c.intersects(&q.bounds())),
            "{:?}",
            q.bounds()
        );
        assert!(q.bounds().min.x > 30.0 && q.bounds().max.y < 0.0);
    }

    /// A text barely narrower than its dimension (the tip thickness s_a of a pointed tooth,
    /// 5 mm drawn) does not stand crowded between the extension lines, which run 2 mm past
    /// the dimension line into its height: it is written past an arrow, clear of them; a
    /// wide dimension keeps its text over the middle.
    #[test]
    fn a_text_crowded_between_its_extension_lines_goes_past_an_arrow() {
        let map = Map::figure(DVec2::ZERO);
        let dim = (DVec2::ZERO, DVec2::new(5.0, 0.0), -6.0);
        let extensions = extension_lines(map, dim);
        let middle = dimension_text(map, dim, "s_{a}", TextSpot::MIDDLE).expect("text");
        assert!(middle.bounds().width() > 3.4, "{:?}", middle.bounds());
        assert!(struck(&middle, &extensions, OWN_CLEAR_MM) > 0.0);
        let (p, _) = placed(map, dim, "s_{a}", (&[], &[]), &[]).expect("placed");
        assert_eq!(struck(&p, &extensions, OWN_CLEAR_MM), 0.0);
        let b = p.bounds();
        assert!(b.min.x > 5.0 || b.max.x < 0.0, "{b:?}");
        let wide = (DVec2::ZERO, DVec2::new(20.0, 0.0), -6.0);
        let (q, _) = placed(map, wide, "s_{a}", (&[], &[]), &[]).expect("placed");
        let over = dimension_text(map, wide, "s_{a}", TextSpot::MIDDLE).expect("text");
        assert_eq!(q.at, over.at);
    }

    #[test]
    fn a_line_nearer_than_its_own_slides_the_text_away_from_it() {
        let map = Map::figure(DVec2::ZERO);
        let dim = (DVec2::ZERO, DVec2::new(60.0, 0.0), 0.0);
        let own = vec![Outline {
            shape: Shape::Line(map.pt(dim.0), map.pt(dim.1)),
            main: false,
        }];
        let middle = dimension_text(map, dim, "H", TextSpot::MIDDLE).expect("text");
        let top = middle.bounds().min.y;
        // A ray 0,4 mm over the middle text's box (clear of it, but nearer than the
        // dimension line 1 mm under it), over the middle third of the line only.
        let ray = Outline {
            shape: Shape::Line(DVec2::new(20.0, top - 0.4), DVec2::new(40.0, top - 0.4)),
            main: false,
        };
        let lines = vec![own[0].clone(), ray.clone()];
        assert_eq!(struck(&middle, &lines, CLEAR_MM), 0.0);
        assert!(wrong_line(&middle.bounds(), &lines, &own) > 0.0);
        let (p, _) = placed(map, dim, "H", (&lines, &own), &[]).expect("placed");
        assert_eq!(wrong_line(&p.bounds(), &lines, &own), 0.0);
        let b = p.bounds();
        assert!(b.max.x < 20.0 || b.min.x > 40.0, "{b:?}");
        assert!(b.max.y < 0.0, "still over its line: {b:?}");
        // Without its own lines nothing is nearer: the middle stays.
        let (q, _) = placed(map, dim, "H", (&lines, &[]), &[]).expect("placed");
        assert_eq!(q.at, middle.at);
    }

    #[test]
    fn a_line_with_no_clear_place_beside_it_takes_its_text_to_a_leader() {
        let map = Map::figure(DVec2::ZERO);
        // A dimension 10 mm long in a comb of upright lines 2 mm apart, 16 mm tall: every
        // place beside the line or past its arrows is struck through.
        let dim = (DVec2::ZERO, DVec2::new(10.0, 0.0), 0.0);
        let comb: Vec<Outline> = (-30..=40)
            .step_by(2)
            .map(|x| Outline {
                shape: Shape::Line(
                    DVec2::new(x as f64 + 0.5, -8.0),
                    DVec2::new(x as f64 + 0.5, 8.0),
                ),
                main: false,
            })
            .collect();
        let (p, l) = placed(map, dim, "H", (&comb, &[]), &[]).expect("placed");
        let l = l.expect("a leader");
        assert_eq!(struck(&p, &comb, CLEAR_MM), 0.0);
        assert_eq!(p.rotate, 0.0, "level on its shelf");
        // From the middle of the line, no dot, the text on the shelf.
        assert!(l.to.distance(DVec2::new(5.0, 0.0)) < 1e-9 && l.from == l.to && !l.dot);
        let b = p.bounds();
        assert!(
            b.max.y <= l.knee.y && b.min.x < l.knee.x.max(l.end.x),
            "{b:?} {l:?}"
        );
        // With room beside the line, no leader.
        let (_, none) = placed(map, dim, "H", (&[], &[]), &[]).expect("placed");
        assert!(none.is_none());
    }
}
