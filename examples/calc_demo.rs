//! Graphical differentiation and integration on one A3 plate: S(φ), its chord derivative
//! dS/dφ and second derivative d²S/dφ² (left), and dS/dφ integrated back to S (right).
//! Writes `/tmp/calc_demo.svg` and `/tmp/calc_demo.png`.
//!
//! Usage: `cargo run --example calc_demo [width_px]`.

use std::f64::consts::TAU;
use std::path::Path;
use tmm::calculus::{
    derivative_scale, integral_scale, integrate_chords, pole_for, Derivation, Diagram,
    DiagramLayout, Sampling, Scales,
};
use tmm::construct::{Context, Drafting, Figure, Recorder};
use tmm::geom::DVec2;
use tmm::plate::{
    to_png, to_svg, write_atomic, Plate, Sheet, SheetSize, TextBlock, TitleBlock, View,
};
use tmm::scale::{format_number, Lang, Quantity, Scale};

type Res<T> = Result<T, Box<dyn std::error::Error>>;

fn recorder(title: &str, s: Scale) -> Res<Recorder> {
    Ok(Recorder::in_context(
        title,
        s,
        &Context::for_model_size(400.0, Drafting::EXACT)?,
    ))
}

fn mu(x: f64, q: Quantity) -> Res<Scale> {
    Scale::new(x, q).ok_or_else(|| format!("bad scale {x}").into())
}

fn main() -> Res<()> {
    let width = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(2400);
    let lang = Lang::Ru;
    let n = |x: f64| format_number(x, lang);
    let s = Diagram::sample(0.0, TAU, 12, true, |x| {
        0.2 * (1.0 - x.cos()) + 0.05 * (2.0 * x).sin()
    })?;
    let mu_phi = mu(0.052, Quantity::Angle)?;
    let mu_s = mu(0.01, Quantity::Length)?;
    let sc = Scales { x: mu_phi, y: mu_s };

    // Left column: S → dS/dφ → d²S/dφ².
    let h1 = pole_for(&s, sc, 20.0)?;
    let mu_v = derivative_scale(mu_s, mu_phi, h1, Quantity::Length)?;
    let mut rec1 = recorder("dS/dφ", mu_v)?;
    let lay1 = DiagramLayout::new(DVec2::ZERO, DVec2::new(0.0, -44.0)).pole_named("P_1", "H_1");
    let d1 = Derivation::Chords.differentiate(&mut rec1, &s, sc, h1, &lay1)?;
    let v = d1.diagram()?;
    let sc2 = Scales { x: mu_phi, y: mu_v };
    let h2 = pole_for(&v, sc2, 20.0)?;
    let mu_a = derivative_scale(mu_v, mu_phi, h2, Quantity::Length)?;
    let mut rec2 = recorder("d²S/dφ²", mu_a)?;
    let lay2 = DiagramLayout::new(lay1.origin, DVec2::new(0.0, -108.0))
        .named("φ", "dS/dφ", "d^2S/dφ^2")
        .pole_named("P_2", "H_2")
        .with_source(false);
    let d2 = Derivation::Chords.differentiate(&mut rec2, &v, sc2, h2, &lay2)?;

    // Right column: dS/dφ (mid-interval values) integrated back to S.
    let x_r = 200.0;
    let mid = Diagram::new(s.x0, s.dx, d1.mid.clone(), true)?;
    let mu_int = integral_scale(mu_v, mu_phi, h1, Quantity::Length)?;
    let mut rec3 = recorder("S", mu_int)?;
    let lay3 = DiagramLayout::new(DVec2::new(x_r, -20.0), DVec2::new(x_r, -110.0))
        .named("φ", "dS/dφ", "S")
        .pole_named("P_3", "H_3");
    let int = integrate_chords(&mut rec3, &mid, Sampling::Midpoints, sc2, h1, 0.0, &lay3)?;

    let sheet = Sheet {
        size: SheetSize::A3,
        landscape: true,
    };
    let origin = DVec2::new(80.0, 78.0);
    let view = |figure: Figure| View {
        figure,
        origin,
        caption: None,
        caption_drop: 0.0,
    };
    let texts = vec![TextBlock {
        at: DVec2::new(30.0, 224.0),
        lines: vec![
            format!(
                "μ_{{φ}} = {} рад/мм,  μ_{{S}} = {} м/мм,  N = {} интервалов",
                n(mu_phi.value()),
                n(mu_s.value()),
                s.intervals()
            ),
            format!(
                "H_1 = {} мм,  μ_{{S′}} = μ_S/(H_1·μ_φ) = {} м/мм",
                n(h1),
                n(mu_v.value())
            ),
            format!(
                "H_2 = {} мм,  μ_{{S″}} = μ_{{S′}}/(H_2·μ_φ) = {} м/мм",
                n(h2),
                n(mu_a.value())
            ),
            format!(
                "H_3 = {} мм,  μ_S = μ_{{S′}}·H_3·μ_φ = {} м/мм,  S(2π) = {} м",
                n(h1),
                n(int.scale.value()),
                n(int.node.last().copied().unwrap_or(f64::NAN))
            ),
        ],
        size_mm: 3.5,
    }];
    let plate = Plate {
        name: "calc_demo".into(),
        sheet,
        title_block: TitleBlock {
            title: "Графическое дифференцирование".into(),
            sheet_title: "Метод хорд".into(),
            designation: "ТММ.КП.00.00.001".into(),
            scale: "1:1".into(),
            sheet_no: 1,
            sheets: 1,
            ..TitleBlock::default()
        },
        lang,
        views: vec![
            view(rec1.finish()),
            view(rec2.finish()),
            view(rec3.finish()),
        ],
        texts,
        tables: Vec::new(),
    };
    let svg = to_svg(&plate);
    write_atomic(Path::new("/tmp/calc_demo.svg"), svg.as_bytes())?;
    write_atomic(Path::new("/tmp/calc_demo.png"), &to_png(&svg, width)?)?;
    println!(
        "wrote /tmp/calc_demo.svg and /tmp/calc_demo.png ({width} px); H1 = {h1} mm, \
         H2 = {h2} mm; d²S/dφ² at φ = 0: {:.4} (exact 0.2)",
        d2.node.first().copied().unwrap_or(f64::NAN)
    );
    Ok(())
}
