//! What the notes' plans read, shared by the plans' subsections and their worked parts: the
//! study, the mechanism and the worked position ([`Plans`]), a plan's segment as it is named
//! (`p b_{3}`), and one symbol explained.

use super::equations::Kind;
use super::Writer;
use crate::check::{Method, Symbol};
use crate::linkage::{Mechanism, PlanPosition, Structure};
use crate::scale::Scale;
use crate::study::Kinematics;

/// What the plans' subsections read: the study, the mechanism, its structure and the
/// worked position.
pub(super) struct Plans<'k> {
    pub(super) kin: &'k Kinematics,
    pub(super) m: &'k Mechanism,
    pub(super) s: &'k Structure,
    pub(super) at: Option<String>,
}

impl Plans<'_> {
    /// The worked position as the plan of positions constructed it.
    pub(super) fn built(&self) -> Option<&PlanPosition> {
        let at = self.at.as_deref()?;
        self.kin.plan.positions.iter().find(|p| p.label == at)
    }

    /// The μ of the worked position's plan of `kind` — its own when the scene gives it one
    /// (`kinematics.own_scale`, `own_scale_a`) — else the common μ of the kind.
    pub(super) fn scale(&self, kind: Kind) -> Scale {
        let at = self.at.as_deref();
        let k = self
            .kin
            .plan
            .positions
            .iter()
            .position(|p| Some(p.label.as_str()) == at);
        let own = k.and_then(|k| match kind {
            Kind::Velocity => self.kin.velocity[k].plan().map(|p| p.figure.scale),
            Kind::Acceleration => self
                .kin
                .acceleration
                .iter()
                .find(|(i, _)| *i == k)
                .map(|(_, a)| a.plan.figure.scale),
        });
        own.unwrap_or(match kind {
            Kind::Velocity => self.kin.scales.v,
            Kind::Acceleration => self.kin.scales.a,
        })
    }

    /// The distance between the mechanism's points `a` and `b` at the worked position on the
    /// plan of positions, mm.
    pub(super) fn drawn(&self, a: &str, b: &str) -> Option<f64> {
        let p = self.built()?;
        let prog = &self.kin.plan.program;
        let (i, j) = (prog.index(a)?, prog.index(b)?);
        Some(p.built.p[i].distance(p.built.p[j]))
    }

    /// The report's graphical value of `symbol` of `subject` at the worked position.
    pub(super) fn value(&self, w: &Writer<'_, '_>, symbol: Symbol, subject: &str) -> Option<f64> {
        let at = self.at.as_deref()?;
        w.report
            .rows
            .iter()
            .find(|r| {
                r.method == Method::Plan
                    && r.key.symbol == symbol
                    && r.key.subject == subject
                    && r.position().as_deref() == Some(at)
            })
            .map(|r| r.graphical)
    }
}

/// The segment of the plan a velocity or acceleration is drawn as: `p b_{3}` (from the
/// pole) or `b_{1} b_{3}` (relative).
pub(super) fn segment(pole: &str, subject: &str) -> String {
    let point = |p: &str| {
        let mut c = p.chars();
        let first = c
            .next()
            .map(|f| f.to_lowercase().to_string())
            .unwrap_or_default();
        let rest: String = c.collect();
        if rest.is_empty() {
            first
        } else {
            format!("{first}_{{{rest}}}")
        }
    };
    match subject.split_once('_') {
        Some((x, y)) => format!("{}{}", point(y), point(x)),
        None => format!("{pole}{}", point(subject)),
    }
}

/// A formula's symbol explained by a meaning built for it (a point's name in it).
pub(super) fn explain_one(w: &mut Writer<'_, '_>, symbol: &str, meaning: &str, si: &str) {
    w.explain(&[(symbol, meaning, si)]);
}
