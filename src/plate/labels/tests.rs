use super::candidates::{self, candidates, POINT_REACH_MM};
use super::clip::{clipped_area, clipped_length};
use super::*;

fn rect(x0: f64, y0: f64, x1: f64, y1: f64) -> Rect {
    Rect::new(DVec2::new(x0, y0), DVec2::new(x1, y1))
}

#[test]
fn clipping_measures_what_lies_inside() {
    let r = rect(0.0, 0.0, 10.0, 10.0);
    let l = clipped_length(DVec2::new(-5.0, 5.0), DVec2::new(15.0, 5.0), &r);
    assert!((l - 10.0).abs() < 1e-9);
    assert_eq!(
        clipped_length(DVec2::new(-5.0, 11.0), DVec2::new(15.0, 11.0), &r),
        0.0
    );
    let square = [
        DVec2::new(5.0, 5.0),
        DVec2::new(15.0, 5.0),
        DVec2::new(15.0, 15.0),
        DVec2::new(5.0, 15.0),
    ];
    assert!((clipped_area(&square, &r) - 25.0).abs() < 1e-9);
    assert_eq!(clipped_area(&square, &rect(20.0, 20.0, 30.0, 30.0)), 0.0);
}

#[test]
fn rectangles_touching_do_not_intersect() {
    let a = rect(0.0, 0.0, 1.0, 1.0);
    assert!(!a.intersects(&rect(1.0, 0.0, 2.0, 1.0)));
    assert!(a.intersects(&rect(0.5, 0.5, 2.0, 2.0)));
    assert!(a.inflate(1.0).contains(&a));
}

fn request(name: &str, at: DVec2, step: u32) -> Request {
    Request {
        view: 0,
        steps: vec![StepId(step)],
        names: vec![name.into()],
        anchor: at,
        toward: DVec2::X,
        gap: LABEL_GAP_MM,
        within: None,
        column: None,
        names_of: Names::Point,
        own: Vec::new(),
    }
}

#[test]
fn coincident_labels_join_with_the_pole_first() {
    let o = DVec2::new(10.0, 10.0);
    let joined = join_coincident(vec![
        request("b_3", o, 1),
        request("c", o + DVec2::new(5.0, 0.0), 2),
        request("d", o + DVec2::new(0.2, 0.0), 3),
        request("p", o + DVec2::new(0.1, 0.1), 4),
        request("d", o, 5),
        request("1", o, 6),
    ]);
    assert_eq!(joined.len(), 3);
    assert_eq!(joined[0].text(), "p ≡ b_3 ≡ d");
    assert_eq!(joined[0].steps.len(), 4);
    assert_eq!(joined[1].text(), "c");
    assert_eq!(joined[2].text(), "1");
}

/// "≡" joins only points within the drafting resolution (0,5 mm) of each other: the
/// tangent's `a` 1,6 mm from the pole and `k` 3,2 mm from it are written apart (issue 45),
/// and a chain of near points does not join its ends 0,9 mm apart.
#[test]
fn only_points_within_the_drafting_resolution_are_joined() {
    assert_eq!(COINCIDENT_MM, 0.5);
    let o = DVec2::new(10.0, 10.0);
    let joined = join_coincident(vec![
        request("p", o, 1),
        request("a", o + DVec2::new(1.6, 0.0), 2),
        request("k", o + DVec2::new(0.0, 3.2), 3),
        request("b", o + DVec2::new(0.45, 0.0), 4),
        request("c", o + DVec2::new(0.9, 0.0), 5),
    ]);
    let texts: Vec<String> = joined.iter().map(Request::text).collect();
    assert_eq!(texts, ["p ≡ b", "a", "k", "c"]);
}

#[test]
fn labels_of_items_are_never_joined() {
    let o = DVec2::new(10.0, 10.0);
    let force = |name: &str, step| Request {
        names_of: Names::Item,
        ..request(name, o, step)
    };
    let joined = join_coincident(vec![
        force("R_{1-2}", 1),
        force("R_{2-3}", 2),
        request("b", o, 3),
        request("s_3", o, 4),
    ]);
    let texts: Vec<String> = joined.iter().map(Request::text).collect();
    assert_eq!(texts, ["R_{1-2}", "R_{2-3}", "b ≡ s_3"]);
}

#[test]
fn candidates_keep_the_gap_and_start_with_the_preferred_side() {
    let mut r = request("B", DVec2::new(50.0, 50.0), 0);
    // A label of an item without lines of its own: the rings alone.
    r.names_of = Names::Item;
    let size = DVec2::new(3.0, 4.0);
    let c = candidates(&r, size);
    assert_eq!(c.len(), RINGS * DIRECTIONS);
    assert!(
        (c[0].min.x - 50.0 - LABEL_GAP_MM).abs() < 1e-9,
        "{:?}",
        c[0]
    );
    assert!((c[0].center().y - 50.0).abs() < 1e-9);
    for b in &c {
        assert!((b.size() - size).length() < 1e-9);
        let gap = (b.min - r.anchor).max(r.anchor - b.max).max(DVec2::ZERO);
        assert!(gap.length() >= LABEL_GAP_MM * 0.7 - 1e-9, "{b:?}");
    }
}

#[test]
fn a_joint_label_is_also_tried_from_each_corner_of_its_point() {
    let at = DVec2::new(50.0, 50.0);
    let mut r = request("d_{5}", at, 0);
    r.names.extend(["e".to_string(), "s_5".to_string()]);
    let size = DVec2::new(25.0, 4.0);
    let c = candidates(&r, size);
    // Seven near rings (gap 1 to 7 mm) of thirty-two directions, two far ones of sixteen.
    assert_eq!(c.len(), 7 * (2 * DIRECTIONS + 4) + 2 * (DIRECTIONS + 4));
    // After the thirty-two directions of the first ring: the four quadrants, the preferred
    // side (+x) first; each box wholly in its quadrant, its corner the gap from the point
    // on both axes, so that neither line through the point meets it.
    let corners = &c[2 * DIRECTIONS..2 * DIRECTIONS + 4];
    assert!(
        corners[0].min.x > at.x && corners[1].min.x > at.x,
        "{corners:?}"
    );
    for b in corners {
        assert!((b.size() - size).length() < 1e-9);
        let dx = (b.min.x - at.x).max(at.x - b.max.x);
        let dy = (b.min.y - at.y).max(at.y - b.max.y);
        assert!((dx - LABEL_GAP_MM).abs() < 1e-9 && (dy - LABEL_GAP_MM).abs() < 1e-9);
    }
    // A single name keeps the directions only.
    assert_eq!(
        candidates(&request("b", at, 0), size).len(),
        7 * 2 * DIRECTIONS + 2 * DIRECTIONS
    );
}

#[test]
fn a_label_kept_near_its_point_has_only_the_near_places() {
    let at = DVec2::new(50.0, 50.0);
    let size = DVec2::new(6.0, 3.5);
    let free = candidates(&request("P", at, 0), size);
    let mut near = request("P", at, 0);
    near.within = Some(4.0);
    let kept = candidates(&near, size);
    // Four rings (gap 1, 2, 3, 4 mm) of thirty-two directions.
    assert_eq!(kept.len(), 4 * 32);
    assert!(kept
        .iter()
        .all(|c| candidates::box_distance(c, at) <= 4.0 + 1e-9));
    assert!(free.iter().any(|c| candidates::box_distance(c, at) > 10.0));
    assert_eq!(kept[0], free[0]);
}

#[test]
fn a_label_of_a_point_is_tried_densely_within_its_reach_first() {
    let at = DVec2::new(50.0, 50.0);
    let size = DVec2::new(6.0, 3.5);
    let c = candidates(&request("B", at, 0), size);
    let d: Vec<f64> = c.iter().map(|b| candidates::box_distance(b, at)).collect();
    let near = d
        .iter()
        .take_while(|x| **x <= POINT_REACH_MM + 1e-9)
        .count();
    // Every place within the reach comes before any beyond it, and there are places beyond
    // (taken at a cost when every near one is struck).
    assert_eq!(near, 7 * 2 * DIRECTIONS);
    assert!(d[near..].iter().all(|x| *x > POINT_REACH_MM));
    assert!(!d[near..].is_empty());
}

#[test]
fn a_label_of_an_item_is_also_tried_along_its_own_line_on_both_sides() {
    let (a, b) = (DVec2::new(0.0, 0.0), DVec2::new(40.0, 0.0));
    let mut r = request("R_{1-2}", a.lerp(b, 0.5), 0);
    r.names_of = Names::Item;
    r.toward = DVec2::new(0.0, -1.0);
    r.own = vec![Outline {
        shape: Shape::Line(a, b),
        main: true,
    }];
    let size = DVec2::new(8.0, 3.5);
    let c = candidates(&r, size);
    let along = &c[DIRECTIONS..DIRECTIONS + 28];
    // The middle first, on the preferred side (above, y down), its gap from the line.
    assert!((along[0].center().x - 20.0).abs() < 1e-9, "{:?}", along[0]);
    assert!(
        (along[0].max.y + LABEL_GAP_MM).abs() < 1e-9,
        "{:?}",
        along[0]
    );
    assert!(
        (along[1].min.y - LABEL_GAP_MM).abs() < 1e-9,
        "{:?}",
        along[1]
    );
    // Every place along is beside the line, none over it, and they cover both halves.
    assert!(along.iter().all(|b| b.min.y > 0.0 || b.max.y < 0.0));
    assert!(along.iter().any(|b| b.center().x < 8.0));
    assert!(along.iter().any(|b| b.center().x > 32.0));
    assert_eq!(c.len(), RINGS * DIRECTIONS + 28);
}
