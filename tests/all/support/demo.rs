//! A demonstration plate with every item kind and every role (`tests/all/plate_demo.rs` and
//! `examples/plate_demo.rs` include this file by path).

use tmm::construct::{Figure, Item, Label, Role, Step, StepId};
use tmm::geom::{Arc, Circle, DVec2, Segment, Side};
use tmm::plate::{Plate, PlateError, Rect, Sheet, TextBlock, TitleBlock, View};
use tmm::scale::{Lang, Quantity, Scale};

/// Steps being collected into a figure.
struct Steps(Vec<Step>);

impl Steps {
    fn add(&mut self, item: Item, role: Role, label: Option<(&str, DVec2, DVec2)>) -> &mut Self {
        let label = label.map(|(text, anchor, toward)| Label::on(&item, text, anchor, toward));
        let id = StepId(self.0.len() as u32);
        self.0.push(Step {
            id,
            note: String::new(),
            item,
            role,
            label,
            from: Vec::new(),
            group: 0,
        });
        self
    }
    fn figure(self, title: &str, scale: Scale) -> Figure {
        Figure {
            title: title.into(),
            scale,
            steps: self.0,
            readings: Vec::new(),
        }
    }
}

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// A slider-crank mechanism at φ₁ = 60°: every [`Item`] kind and every [`Role`].
pub fn demo_mechanism(mu_l: Scale) -> Figure {
    let (a, b) = (DVec2::ZERO, DVec2::from_angle(60f64.to_radians()) * 40.0);
    let c = v(b.x + (110f64.powi(2) - b.y * b.y).sqrt(), 0.0);
    let s2 = (b + c) * 0.5;
    let mut s = Steps(Vec::new());
    mechanism_items(&mut s, [a, b, c, s2]);
    marking_items(&mut s, [a, b, c, s2]);
    s.figure("План механизма", mu_l)
}

/// The mechanism's own items: the axis, the crank's circle, a notch, the guide, the links,
/// the joints (`[A, B, C, S₂]` its points).
fn mechanism_items(s: &mut Steps, [a, b, c, s2]: [DVec2; 4]) {
    s.add(
        Item::Segment(Segment::new(v(-50.0, 0.0), v(170.0, 0.0))),
        Role::Axis,
        None,
    )
    .add(
        Item::Circle(Circle {
            center: a,
            radius: 40.0,
        }),
        Role::Construction,
        None,
    )
    .add(Item::Arc(Arc::notch(b, c, 6.0)), Role::Construction, None)
    .add(
        Item::Guide {
            segment: Segment::new(v(c.x - 30.0, -3.0), v(c.x + 30.0, -3.0)),
            hatch: Side::Right,
        },
        Role::Given,
        None,
    )
    .add(
        Item::Segment(Segment::new(a, b)),
        Role::Given,
        Some(("1", (a + b) * 0.5, v(-0.8, 0.6))),
    )
    .add(
        Item::Segment(Segment::new(b, c)),
        Role::Given,
        Some(("2", s2 + v(20.0, -7.5), v(0.3, 1.0))),
    )
    .add(
        Item::Slider { at: c, angle: 0.0 },
        Role::Given,
        Some(("3", c + v(0.0, 3.0), v(0.0, 1.0))),
    )
    .add(
        Item::Joint { at: a, fixed: true },
        Role::Given,
        Some(("A", a, v(-1.0, 0.3))),
    )
    .add(
        Item::Joint {
            at: b,
            fixed: false,
        },
        Role::Given,
        Some(("B", b, v(0.0, 1.0))),
    )
    .add(
        Item::Joint {
            at: c,
            fixed: false,
        },
        Role::Given,
        Some(("C", c, v(1.0, 1.0))),
    );
}

/// The marks on the mechanism: points, vectors, an angle, a dimension, polylines, a curve
/// and a text (`[A, B, C, S₂]` its points).
fn marking_items(s: &mut Steps, [a, b, c, s2]: [DVec2; 4]) {
    s.add(
        Item::Point(s2),
        Role::Result,
        Some(("S_2", s2, v(0.0, -1.0))),
    )
    .add(Item::Point(v(60.0, 20.0)), Role::Construction, None)
    .add(
        Item::Vector {
            from: b,
            to: b + v(-b.y, b.x) * 0.75,
        },
        Role::Result,
        Some(("V_B", b + v(-b.y, b.x) * 0.75, v(-1.0, 0.0))),
    )
    .add(
        Item::Vector {
            from: b,
            to: b * 0.5,
        },
        Role::Construction,
        Some(("a^n_{B}", b * 0.5, v(1.0, 0.0))),
    )
    .add(
        Item::Angle(Arc {
            center: a,
            radius: 16.0,
            start: 0.0,
            sweep: 60f64.to_radians(),
        }),
        Role::Dimension,
        Some(("φ_1", a + DVec2::from_angle(0.5) * 16.0, v(1.0, 0.3))),
    )
    .add(
        Item::Dimension {
            from: a,
            to: c,
            offset: -22.0,
        },
        Role::Dimension,
        Some(("124,4", a, DVec2::ZERO)),
    )
    .add(
        Item::Polyline {
            points: vec![
                v(-20.0, -30.0),
                v(-10.0, -30.0),
                v(-10.0, -40.0),
                v(-20.0, -40.0),
            ],
            closed: true,
        },
        Role::Given,
        None,
    )
    .add(
        Item::Polyline {
            points: (0..4)
                .map(|k| v(-20.0 + 2.5 * k as f64, -40.0))
                .flat_map(|p| [p, p + v(2.5, 2.5)])
                .collect(),
            closed: false,
        },
        Role::Hatch,
        None,
    )
    .add(
        Item::Curve {
            points: (0..12)
                .map(|k| {
                    s2 + DVec2::from_angle(k as f64 * std::f64::consts::FRAC_PI_6) * v(22.0, 9.0)
                })
                .collect(),
            closed: true,
        },
        Role::Result,
        Some(("траектория S_2", s2 + v(22.0, 0.0), v(1.0, -0.2))),
    )
    .add(
        Item::Text(v(60.0, 60.0)),
        Role::Dimension,
        Some(("ω_1 = 10 рад/с, l_{AB} = 0,1 м", v(60.0, 60.0), DVec2::ZERO)),
    );
}

/// A velocity plan: the pole and vectors with subscripted and superscripted labels.
pub fn demo_velocity_plan(mu_v: Scale) -> Figure {
    let (p, b, c) = (DVec2::ZERO, v(-52.0, 30.0), v(-36.0, 0.0));
    let mut s = Steps(Vec::new());
    s.add(Item::Point(p), Role::Given, Some(("p_v", p, v(1.0, -0.5))))
        .add(
            Item::Vector { from: p, to: b },
            Role::Result,
            Some(("b", b, v(-0.7, 0.7))),
        )
        .add(
            Item::Vector { from: p, to: c },
            Role::Result,
            Some(("c", c, v(0.0, -1.0))),
        )
        .add(
            Item::Vector { from: b, to: c },
            Role::Result,
            Some(("cb", (b + c) * 0.5, v(1.0, 0.3))),
        )
        .add(
            Item::Segment(Segment::new(v(-70.0, 0.0), v(10.0, 0.0))),
            Role::Construction,
            Some(("∥ x", v(10.0, 0.0), v(1.0, 0.0))),
        );
    s.figure("План скоростей", mu_v)
}

fn scale(value: f64, quantity: Quantity) -> Result<Scale, PlateError> {
    Scale::new(value, quantity).ok_or_else(|| PlateError::Svg(format!("invalid scale {value}")))
}

/// An A1 plate with the demo figures, title block filled, in `lang`.
///
/// # Errors
/// Never in practice; [`PlateError::DoesNotFit`] if a demo figure outgrew its region.
pub fn demo_plate(lang: Lang) -> Result<Plate, PlateError> {
    let sheet = Sheet::default();
    let field = sheet.field();
    let half = field.min.x + field.width() * 0.5;
    let left = Rect::new(field.min, v(half, field.max.y));
    let right = Rect::new(v(half, field.min.y), field.max);
    let mech = demo_mechanism(scale(0.0025, Quantity::Length)?);
    let plan = demo_velocity_plan(scale(0.04, Quantity::Velocity)?);
    let cap_m = format!("{}, {}", mech.title, mech.scale.caption(lang));
    let cap_v = format!("{}, {}", plan.title, plan.scale.caption(lang));
    let views = vec![
        View::centred(mech, left, Some(cap_m))?,
        View::centred(plan, right, Some(cap_v))?,
    ];
    let texts = vec![TextBlock {
        at: v(40.0, 40.0),
        lines: vec![
            "Дано: l_{AB} = 0,1 м; l_{BC} = 0,275 м".into(),
            "ω_1 = 10 с^{-1}, φ_1 = 60°".into(),
        ],
        size_mm: 5.0,
    }];
    let title_block = TitleBlock {
        title: "Кривошипно-ползунный механизм".into(),
        sheet_title: "Кинематический анализ".into(),
        designation: "ТММ.КП.01.00.000".into(),
        author: "Иванов И. И.".into(),
        checked: "Петров П. П.".into(),
        organisation: "Каф. ТММ, гр. М-21".into(),
        scale: "1:1".into(),
        sheet_no: 1,
        sheets: 3,
        ..TitleBlock::default()
    };
    Ok(Plate {
        name: "demo".into(),
        sheet,
        title_block,
        lang,
        views,
        texts,
        tables: Vec::new(),
    })
}
