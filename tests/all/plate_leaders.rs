//! The leader rules (issue 45, ГОСТ 2.316), on every sheet of every scene in
//! `constructions/` in every configuration of [`plate_label_objects`](crate::plate_label_objects),
//! computed from the plate's layout: no leader runs through another label or crosses
//! another leader, and no shelf stands right over another text (read as a fraction's bar).

use crate::plate_label_objects::{labels_away_in, on_every_layout};
use crate::plate_model::sheet;
use glam::DVec2;
use tmm::plate::{layout, Layout};

/// A text whose top stands at most this far under a shelf, across from half of the shorter
/// of the two, reads as the denominator of a fraction the shelf is the bar of (`0` over
/// `O₂`, issue 45), mm.
const UNDER_SHELF_MM: f64 = 2.5;

/// Where the leaders of the layout `l` break ГОСТ 2.316: a leader (its line or shelf) through
/// another label's text, two leaders crossing, a shelf right over another text; `view N
/// “text”: why` for each.
fn leaders_crossing(l: &Layout) -> Vec<String> {
    let mut out = Vec::new();
    for (i, x) in l.labels.iter().enumerate() {
        let Some(leader) = &x.leader else { continue };
        let pieces = leader.pieces();
        for (j, y) in l.labels.iter().enumerate().filter(|(j, _)| *j != i) {
            let inside = |p: DVec2| {
                p.x > y.rect.min.x && p.x < y.rect.max.x && p.y > y.rect.min.y && p.y < y.rect.max.y
            };
            // Sampled every 0,1 mm: a leader through a text crosses it over more than that.
            let through = pieces.iter().any(|s| {
                let n = (s.length() / 0.1).ceil().max(1.0) as usize;
                (0..=n).any(|k| inside(s.eval(k as f64 / n as f64)))
            });
            if through {
                out.push(format!(
                    "view {} “{}”: its leader runs through “{}”",
                    x.view, x.text, y.text
                ));
            }
            let crosses = y.leader.is_some_and(|other| {
                other
                    .pieces()
                    .iter()
                    .any(|o| pieces.iter().any(|s| s.crossing(o).is_some()))
            });
            if crosses && j > i {
                out.push(format!(
                    "view {} “{}”: its leader crosses “{}”'s",
                    x.view, x.text, y.text
                ));
            }
            let (lo, hi) = (
                leader.knee.x.min(leader.end.x),
                leader.knee.x.max(leader.end.x),
            );
            let across = hi.min(y.rect.max.x) - lo.max(y.rect.min.x);
            let below = y.rect.min.y - leader.knee.y;
            if across > 0.5 * (hi - lo).min(y.rect.max.x - y.rect.min.x)
                && (0.0..=UNDER_SHELF_MM).contains(&below)
            {
                out.push(format!(
                    "view {} “{}”: its shelf stands right over “{}” (a fraction)",
                    x.view, x.text, y.text
                ));
            }
        }
    }
    out
}

/// No leader on any sheet runs through another label, crosses another leader or stands its
/// shelf right over another label, in every configuration; and the shipped sheets write
/// some labels on leaders (the rule is checked on real leaders).
#[test]
fn leaders_cross_no_label_and_no_leader() {
    let (found, leaders) = on_every_layout(leaders_crossing, |x| x.leader.is_some());
    assert!(found.is_empty(), "{}", found.join("\n"));
    assert!(leaders >= 40, "{leaders} leaders in 4 configurations");
}

/// The leader rules fail where they should: a label moved onto another's leader, a leader
/// moved off its object.
#[test]
fn the_leader_rules_fail_on_a_plate_built_to_break_them() {
    let plate = sheet("shaper/forces");
    let mut l = layout(&plate);
    let on = l
        .labels
        .iter()
        .position(|x| x.leader.is_some())
        .expect("a leader on shaper/forces");
    let leader = l.labels[on].leader.expect("leader");
    assert!(leaders_crossing(&l).is_empty());
    assert!(labels_away_in(&plate, &l)
        .iter()
        .all(|x| !x.1.contains("its leader")));
    // Another label of its view written over the middle of its leader's line.
    let other = (0..l.labels.len())
        .find(|&k| k != on && l.labels[k].view == l.labels[on].view)
        .expect("another label");
    let mid = leader.pieces()[0].eval(0.5);
    let size = l.labels[other].rect.max - l.labels[other].rect.min;
    l.labels[other].rect.min = mid - size * 0.5;
    l.labels[other].rect.max = mid + size * 0.5;
    let crossing = leaders_crossing(&l).join("\n");
    assert!(crossing.contains("its leader runs through"), "{crossing}");
    // Another label written right under its shelf, 1 mm below it.
    let mut l = layout(&plate);
    let (lo, hi) = (
        leader.knee.x.min(leader.end.x),
        leader.knee.x.max(leader.end.x),
    );
    let size = l.labels[other].rect.max - l.labels[other].rect.min;
    l.labels[other].rect.min = DVec2::new((lo + hi - size.x) * 0.5, leader.knee.y + 1.0);
    l.labels[other].rect.max = l.labels[other].rect.min + size;
    let crossing = leaders_crossing(&l).join("\n");
    assert!(crossing.contains("right over"), "{crossing}");
    // The leader moved 1 mm off its object.
    let mut l = layout(&plate);
    if let Some(x) = l.labels[on].leader.as_mut() {
        x.to += DVec2::new(0.8, -0.6);
    }
    let away: Vec<String> = labels_away_in(&plate, &l)
        .into_iter()
        .map(|x| x.1)
        .collect();
    assert!(
        away.iter().any(|w| w.contains("its leader ends")),
        "{away:?}"
    );
}
