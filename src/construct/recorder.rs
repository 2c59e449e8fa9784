//! The recorder: steps drawn one after another into a [`Figure`], with measurement under the
//! drafting model. The compass steps are in [`super::compass`].

use super::context::Context;
use super::drafting::{Drafting, Measured};
use super::figure::{Figure, Role, Step, StepId};
use super::item::Item;
use super::label::{Label, Names};
use super::reading::Reading;
use crate::geom::{DVec2, HatchError, Tolerances};
use crate::scale::Scale;

/// Records a construction into a [`Figure`].
#[derive(Debug, Clone)]
pub struct Recorder {
    figure: Figure,
    ctx: Context,
    group: u32,
}

impl Recorder {
    /// Start a figure at scale `scale` in the context `ctx` (tolerances in figure mm, the
    /// drafting model, the notch size). This is how a construction starts.
    pub fn in_context(title: impl Into<String>, scale: Scale, ctx: &Context) -> Self {
        Self {
            figure: Figure {
                title: title.into(),
                scale,
                steps: Vec::new(),
                readings: Vec::new(),
            },
            ctx: *ctx,
            group: 0,
        }
    }

    /// Go on recording into a finished `figure` in the context `ctx`: its annotations that
    /// wait for names known only later (the positions' numbers on a diagram's axis).
    pub fn resume(figure: Figure, ctx: &Context) -> Self {
        Self {
            figure,
            ctx: *ctx,
            group: 0,
        }
    }

    /// The figure's scale.
    pub fn scale(&self) -> Scale {
        self.figure.scale
    }
    /// The context in use.
    pub fn context(&self) -> &Context {
        &self.ctx
    }
    /// The tolerances in use.
    pub fn tolerances(&self) -> &Tolerances {
        &self.ctx.tol
    }
    /// The drafting model in use.
    pub fn drafting(&self) -> Drafting {
        self.ctx.drafting
    }
    /// Tag the following steps with `group` (e.g. a position number).
    pub fn set_group(&mut self, group: u32) {
        self.group = group;
    }
    /// Half-length of compass notches, mm (default [`Context::NOTCH_MM`]).
    pub fn set_notch_mm(&mut self, mm: f64) {
        self.ctx.notch_mm = mm;
    }
    /// The steps so far.
    pub fn steps(&self) -> &[Step] {
        &self.figure.steps
    }
    /// Axis-aligned bounds of everything drawn so far ([`Figure::bounds`]).
    pub fn bounds(&self) -> Option<(DVec2, DVec2)> {
        self.figure.bounds()
    }
    /// Finish and return the figure.
    pub fn finish(self) -> Figure {
        self.figure
    }

    /// Record a step.
    pub fn draw(
        &mut self,
        note: impl Into<String>,
        item: Item,
        role: Role,
        from: &[StepId],
    ) -> StepId {
        let id = StepId(self.figure.steps.len() as u32);
        self.figure.steps.push(Step {
            id,
            note: note.into(),
            item,
            role,
            label: None,
            from: from.to_vec(),
            group: self.group,
        });
        id
    }

    /// Record the hatching of the closed `outline` (figure mm), its lines `spacing` mm apart
    /// at `angle` radians from +x (ГОСТ 2.306), with the hatch's role: one step however many
    /// lines it draws.
    ///
    /// # Errors
    /// The hatcher's refusal ([`HatchError`]): a coordinate that is not finite, or an outline
    /// too many spacings across.
    pub fn hatching(
        &mut self,
        note: impl Into<String>,
        outline: Vec<DVec2>,
        (spacing, angle): (f64, f64),
        from: &[StepId],
    ) -> Result<StepId, HatchError> {
        crate::geom::hatch(&outline, spacing, angle)?;
        let item = Item::Hatching {
            outline,
            spacing,
            angle,
        };
        Ok(self.draw(note, item, Role::Hatch, from))
    }

    /// Attach a label to a recorded step; it names what [`Names::of`] says (the point it
    /// is anchored at when that is a point of the step's item, else the item).
    pub fn label(&mut self, id: StepId, text: impl Into<String>, anchor: DVec2, toward: DVec2) {
        if let Some(step) = self.figure.steps.get_mut(id.0 as usize) {
            step.label = Some(Label::on(&step.item, text, anchor, toward));
        }
    }

    /// Attach a label that names the step's item wherever it is anchored: a force's arrow
    /// labelled at its free end names the force, not the point there, and is never joined
    /// with another label at that point.
    pub fn label_item(
        &mut self,
        id: StepId,
        text: impl Into<String>,
        anchor: DVec2,
        toward: DVec2,
    ) {
        self.label_naming(id, Names::Item, text.into(), (anchor, toward));
    }

    /// Attach a label that names the point at `anchor` whatever the step's item: a position's
    /// number written at its crank pin (a text item) names that point, is kept near it as a
    /// point's label is, and is never joined with a letter there.
    pub fn label_point(
        &mut self,
        id: StepId,
        text: impl Into<String>,
        anchor: DVec2,
        toward: DVec2,
    ) {
        self.label_naming(id, Names::Point, text.into(), (anchor, toward));
    }

    /// Attach a label that names what `names` says, at `anchor` toward `toward`.
    fn label_naming(
        &mut self,
        id: StepId,
        names: Names,
        text: String,
        (anchor, toward): (DVec2, DVec2),
    ) {
        if let Some(step) = self.figure.steps.get_mut(id.0 as usize) {
            step.label = Some(Label {
                names,
                ..Label::on(&step.item, text, anchor, toward)
            });
        }
    }

    /// Keep the label of step `id` within `mm` of its point on the sheet
    /// ([`Label::within_mm`]).
    pub fn keep_label_within(&mut self, id: StepId, mm: f64) {
        if let Some(label) = self.label_mut(id) {
            label.within_mm = Some(mm);
        }
    }

    /// The label of step `id`, where it has one.
    fn label_mut(&mut self, id: StepId) -> Option<&mut Label> {
        (self.figure.steps.get_mut(id.0 as usize)).and_then(|s| s.label.as_mut())
    }

    /// Keep the label of step `id` in its point's column: its middle at most `mm` left and
    /// right of its point on the sheet, never on a leader ([`Label::column_mm`]).
    pub fn keep_label_in_column(&mut self, id: StepId, mm: [f64; 2]) {
        if let Some(label) = self.label_mut(id) {
            label.column_mm = Some(mm);
        }
    }

    /// Record a dimension of the piece `from`–`to` drawn `offset` mm to its left (negative:
    /// right), its text `text` at the middle of the dimension line, written away from the piece.
    pub fn dimension(
        &mut self,
        note: impl Into<String>,
        (from, to, offset): (DVec2, DVec2, f64),
        text: impl Into<String>,
    ) -> StepId {
        let id = self.draw(
            note,
            Item::Dimension { from, to, offset },
            Role::Dimension,
            &[],
        );
        let n = (to - from).normalize_or_zero().perp();
        self.label(
            id,
            text,
            (from + to) * 0.5 + n * offset,
            n * offset.signum(),
        );
        id
    }

    /// Record a labelled point.
    pub fn point(
        &mut self,
        note: impl Into<String>,
        at: DVec2,
        role: Role,
        label: &str,
        toward: DVec2,
        from: &[StepId],
    ) -> StepId {
        let id = self.draw(note, Item::Point(at), role, from);
        if !label.is_empty() {
            self.label(id, label, at, toward);
        }
        id
    }

    /// Record the pole of a plan (`p`, `π`) at the figure's origin, its label down-left.
    pub fn pole(&mut self, label: &str) -> StepId {
        self.point(
            "pole",
            DVec2::ZERO,
            Role::Given,
            label,
            DVec2::new(-0.7, -0.7),
            &[],
        )
    }

    /// Measure a drawn segment: exact length, length as read, physical value. The figure
    /// keeps it as a [`Reading`] (where the value was read; it draws nothing).
    pub fn measure(&mut self, from: DVec2, to: DVec2) -> Measured {
        let drawn_mm = from.distance(to);
        let read_mm = self.ctx.drafting.read(drawn_mm);
        let value = self.figure.scale.to_physical(read_mm);
        self.figure.readings.push(Reading {
            from,
            to,
            read_mm,
            value,
            group: self.group,
        });
        Measured {
            drawn_mm,
            read_mm,
            value,
        }
    }

    /// The segments measured so far.
    pub fn readings(&self) -> &[Reading] {
        &self.figure.readings
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::construct::{Compass, Pick};
    use crate::scale::Quantity;

    fn rec() -> Recorder {
        let ctx = Context::for_model_size(300.0, Drafting::new(0.5).unwrap()).unwrap();
        Recorder::in_context("test", Scale::new(0.0025, Quantity::Length).unwrap(), &ctx)
    }

    #[test]
    fn a_recorder_keeps_its_context() {
        let mu = Scale::new(0.0025, Quantity::Length).unwrap();
        let tol = Tolerances::for_model_size(300.0).unwrap();
        let ctx = Context::new(tol, Drafting::EXACT);
        let r = Recorder::in_context("t", mu, &ctx);
        assert_eq!(r.context(), &ctx);
        assert_eq!(r.context().notch_mm, Context::NOTCH_MM);
    }

    #[test]
    fn meet_circles_records_two_notches_and_the_point() {
        let mut r = rec();
        let (p, _, id) = r
            .meet_circles(
                "B",
                Compass {
                    name: "A",
                    center: DVec2::ZERO,
                    radius: 5.0,
                },
                Compass {
                    name: "C",
                    center: DVec2::new(8.0, 0.0),
                    radius: 5.0,
                },
                Pick::Left,
            )
            .unwrap();
        assert!((p - DVec2::new(4.0, 3.0)).length() < 1e-12);
        assert_eq!(r.steps().len(), 3);
        assert_eq!(r.steps()[id.0 as usize].from, vec![StepId(0), StepId(1)]);
    }

    #[test]
    fn meet_circles_failure_names_the_step_and_numbers_in_si() {
        let mut r = rec();
        let e = r
            .meet_circles(
                "position 7, B",
                Compass {
                    name: "A",
                    center: DVec2::ZERO,
                    radius: 56.0,
                },
                Compass {
                    name: "C",
                    center: DVec2::new(248.0, 0.0),
                    radius: 172.0,
                },
                Pick::Left,
            )
            .unwrap_err();
        let msg = e.to_string();
        assert!(msg.contains("position 7, B"), "{msg}");
        assert!(
            msg.contains("0.14000 m") && msg.contains("0.62000 m") && msg.contains("0.57000"),
            "{msg}"
        );
        assert!(r.steps().is_empty());
    }

    #[test]
    fn meet_line_circle_picks_by_direction_or_nearness_and_refuses_sides() {
        let mut r = rec();
        let line = crate::geom::Line::new(DVec2::ZERO, DVec2::X).unwrap();
        let c = Compass {
            name: "O",
            center: DVec2::ZERO,
            radius: 5.0,
        };
        let at = |r: &mut Recorder, pick| r.meet_line_circle("K", ("x", &line), c, pick);
        assert_eq!(at(&mut r, Pick::Forward).unwrap().0, DVec2::new(5.0, 0.0));
        assert_eq!(at(&mut r, Pick::Backward).unwrap().0, DVec2::new(-5.0, 0.0));
        let near = at(&mut r, Pick::Near(DVec2::new(-4.0, 1.0))).unwrap().0;
        assert_eq!(near, DVec2::new(-5.0, 0.0));
        let steps = r.steps().len();
        let e = at(&mut r, Pick::Left).unwrap_err();
        assert!(e.to_string().contains("`left`"), "{e}");
        assert_eq!(r.steps().len(), steps);
    }

    #[test]
    fn drafting_rounds_before_scaling() {
        let mut r = rec();
        r.set_group(3);
        let m = r.measure(DVec2::ZERO, DVec2::new(42.6, 0.0));
        // The figure keeps where it was read, and nothing is drawn.
        assert!(r.steps().is_empty());
        let read = r.readings()[0];
        assert_eq!(
            (read.from, read.to, read.group),
            (DVec2::ZERO, DVec2::new(42.6, 0.0), 3)
        );
        assert_eq!((read.read_mm, read.value), (m.read_mm, m.value));
        assert_eq!(m.read_mm, 42.5);
        assert!((m.value - 42.5 * 0.0025).abs() < 1e-15);
        assert!(Drafting::new(-1.0).is_none());
    }
}
