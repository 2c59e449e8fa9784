//! The train in the gears section: what the source leaves out (the module of a stage whose
//! tooth sums do not close) and the module the triangles take for it; the ratio stage by
//! stage (seed 000 §4: each mesh −(±)z_driven/z_driving, the planetary stage by Willis with
//! the carrier stopped, u_aH^(f) = 1 − u_af^(H)) or a differential's output speed by Willis's
//! formula, against Willis's relations solved together; and with the scene's speeds the
//! required ratio, the stage it asks for and the output speed the chosen teeth give.

use super::markup::{frac, num, sym, unit};
use super::worked::{Printed, Worked};
use super::Writer;
use crate::check::{Key, Method, Symbol};
use crate::gears::{uncuttable as uncuttable_by, BasicRack, Stage, Train, TrainStudy};
use crate::scale::RPM;
use crate::words::{unit_in, CaseMeaning as M, NoteText as T};

/// A number of the worked formulas.
fn n(x: f64, lang: crate::scale::Lang) -> String {
    num(x, 5, lang)
}

/// A factor or a subtrahend: a negative one in parentheses.
fn factor(x: f64, lang: crate::scale::Lang) -> String {
    if x < 0.0 {
        format!("({})", n(x, lang))
    } else {
        n(x, lang)
    }
}

/// «где» under a ratio: the ratio's `label` with its meaning and the teeth of the wheels of
/// `meshes`.
fn explain_ratio(
    w: &mut Writer<'_, '_>,
    (label, meaning): (&str, M),
    t: &Train,
    meshes: &[(usize, usize)],
) {
    // Each wheel's number of teeth named with its wheel: «z₁ — число зубьев колеса 1».
    let teeth: Vec<(String, String)> = meshes
        .iter()
        .flat_map(|&(x, y)| [x, y])
        .map(|i| {
            let name = &t.wheels[i].name;
            let meaning = w.word(M::Teeth).replace("{k}", name);
            (format!("z_{{{name}}}"), meaning)
        })
        .collect();
    let mut items = vec![(label, w.word(meaning), "")];
    items.extend(teeth.iter().map(|(z, m)| (z.as_str(), m.as_str(), "")));
    w.explain(&items);
}

/// z_i of wheel `i` in a formula.
fn z(t: &Train, i: usize) -> String {
    sym(&format!("z_{{{}}}", t.wheels[i].name))
}

/// Mesh (x, y)'s ratio ω_x/ω_y in symbols and in numbers, signed.
fn mesh(t: &Train, x: usize, y: usize, lang: crate::scale::Lang) -> (String, String) {
    let sign = if t.mesh_ratio(x, y) < 0.0 { "-" } else { "" };
    (
        format!("{sign}{}", frac(&z(t, y), &z(t, x))),
        format!(
            "{sign}{}",
            frac(&n(t.wheels[y].z, lang), &n(t.wheels[x].z, lang))
        ),
    )
}

/// A chain of meshes' ratios in symbols and in numbers, each in parentheses, joined by dots.
fn chain(t: &Train, meshes: &[(usize, usize)], lang: crate::scale::Lang) -> (String, String) {
    let (symbolic, substituted): (Vec<_>, Vec<_>) = meshes
        .iter()
        .map(|&(x, y)| {
            let (s, v) = mesh(t, x, y, lang);
            (format!("({s})"), format!("({v})"))
        })
        .unzip();
    (symbolic.join(" dot "), substituted.join(" dot "))
}

/// The train worked: the closed stages, then its ratio by the stages (or a differential's
/// output by Willis's formula) against Willis's relations, then the required ratio.
pub(super) fn train_worked(w: &mut Writer<'_, '_>, study: &TrainStudy) {
    uncuttable(w, study);
    closing_worked(w, study);
    let t = &study.spec.train;
    if let Some(stages) = t.stages() {
        let names = stages_worked(w, study, &stages);
        required_worked(w, study, &stages, &names);
    } else {
        differential_worked(w, study);
    }
}

/// Each wheel the standard rack cannot cut, with the shifts that say so (seed 002 PZ2
/// example 1's z₃ = 4, an erratum the source's arithmetic keeps).
fn uncuttable(w: &mut Writer<'_, '_>, study: &TrainStudy) {
    let lang = w.lang;
    for wheel in &study.spec.train.wheels {
        let teeth = wheel.z.round() as u32;
        let Some((least, pointed)) = uncuttable_by(teeth, &BasicRack::GOST_13755) else {
            continue;
        };
        let line = w
            .word(T::TrainUncuttable)
            .replace("{name}", &wheel.name)
            .replace("{z}", &teeth.to_string())
            .replace("{least}", &crate::scale::format_sig(least, 3, lang))
            .replace("{pointed}", &crate::scale::format_sig(pointed, 3, lang));
        w.doc.say(&line);
    }
}

/// Each mesh the train's one module does not close (the module the source leaves out): the
/// carrier's arm by the mesh that sets it, the module that brings the other central wheel
/// onto the carrier's axis.
fn closing_worked(w: &mut Writer<'_, '_>, study: &TrainStudy) {
    if study.closings.is_empty() {
        return;
    }
    let lang = w.lang;
    let t = &study.spec.train;
    let mm = unit(&unit_in("mm", lang));
    w.doc.say(w.word(T::TrainClosing));
    // The teeth across a mesh's centre distance: z_a + z_b, or the ring's less the other's.
    let across = |x: usize, y: usize| {
        let (wx, wy) = (&t.wheels[x], &t.wheels[y]);
        let (ring, other) = match (wx.internal, wy.internal) {
            (true, _) => (Some(x), y),
            (_, true) => (Some(y), x),
            _ => (None, y),
        };
        match ring {
            Some(r) => (
                format!("{} - {}", z(t, r), z(t, other)),
                format!(
                    "{} - {}",
                    n(t.wheels[r].z, lang),
                    n(t.wheels[other].z, lang)
                ),
            ),
            None => (
                format!("{} + {}", z(t, x), z(t, y)),
                format!("{} + {}", n(wx.z, lang), n(wy.z, lang)),
            ),
        }
    };
    for c in &study.closings {
        let ((s, wc), (sa, wa)) = (c.mesh, c.arm_mesh);
        let (arm_sym, arm_num) = across(wa, sa);
        w.worked(Worked::new(
            sym("a"),
            frac(&format!("{} ({arm_sym})", sym("m")), "2"),
            frac(&format!("{} dot ({arm_num})", n(t.module * 1e3, lang)), "2"),
            Printed::mm(c.arm, 5, lang).with_unit(format!(" {mm}")),
        ));
        let (arm, module) = (w.word(M::CarrierArm), w.word(M::Module));
        w.explain(&[("a", arm, "mm"), ("m", module, "mm")]);
        let (sym_, num_) = across(s, wc);
        let label = format!("m'_{{{}{}}}", t.wheels[s].name, t.wheels[wc].name);
        let name = sym(&label);
        w.worked(Worked::new(
            &name,
            frac(&format!("2{}", sym("a")), &sym_),
            frac(&format!("2 dot {}", n(c.arm * 1e3, lang)), &num_),
            Printed::mm(c.module, 5, lang).with_unit(format!(" {mm}")),
        ));
        let closing = w.word(M::ClosingModule);
        w.explain(&[(label.as_str(), closing, "mm")]);
    }
}

/// The ratio stage by stage and their product against Willis's relations; gives each
/// stage's name in the formulas.
fn stages_worked(w: &mut Writer<'_, '_>, study: &TrainStudy, stages: &[Stage]) -> Vec<String> {
    let lang = w.lang;
    let t = &study.spec.train;
    let wheel = |i: usize| t.wheels[i].name.as_str();
    let carrier = t.carrier.map_or("H", |h| t.shafts[h].as_str());
    w.doc.say(w.word(T::TrainWorked));
    let mut names = Vec::new();
    for stage in stages {
        let u = t.stage_ratio(stage);
        match stage {
            Stage::Mesh { driving, driven } => {
                let label = format!("u_{{{}{}}}", wheel(*driving), wheel(*driven));
                let name = sym(&label);
                let (symbolic, substituted) = mesh(t, *driving, *driven, lang);
                w.worked(Worked::new(
                    &name,
                    &symbolic,
                    &substituted,
                    Printed::number(u, lang),
                ));
                explain_ratio(w, (&label, M::StageRatio), t, &[(*driving, *driven)]);
                names.push(name);
            }
            Stage::Planetary { meshes } => {
                let (Some(first), Some(last)) = (meshes.first(), meshes.last()) else {
                    continue;
                };
                let (a, f) = (wheel(first.0), wheel(last.1));
                let (symbolic, substituted) = chain(t, meshes, lang);
                let stopped_label = format!("u_{{{a}{f}}}^{{({carrier})}}");
                let stopped = sym(&stopped_label);
                w.worked(Worked::new(
                    &stopped,
                    &symbolic,
                    &substituted,
                    Printed::number(1.0 - u, lang),
                ));
                explain_ratio(w, (&stopped_label, M::StoppedRatio), t, meshes);
                let label = format!("u_{{{a}{carrier}}}^{{({f})}}");
                let name = sym(&label);
                let substituted = format!("1 - {}", factor(1.0 - u, lang));
                w.worked(Worked::new(
                    &name,
                    format!("1 - {stopped}"),
                    &substituted,
                    Printed::number(u, lang),
                ));
                explain_ratio(w, (&label, M::PlanetaryRatio), t, &[]);
                names.push(name);
            }
        }
    }
    let ratios: Vec<f64> = stages.iter().map(|s| t.stage_ratio(s)).collect();
    let whole = whole(t);
    if stages.len() > 1 {
        let factors: Vec<String> = ratios.iter().map(|&u| factor(u, lang)).collect();
        let total = ratios.iter().product::<f64>();
        w.worked(
            Worked::new(
                &whole,
                names.join(" dot "),
                factors.join(" dot "),
                Printed::number(total, lang),
            )
            .gives_by(ratio_key(t), Method::Formula),
        );
        explain_ratio(w, (&whole_label(t), M::TrainRatio), t, &[]);
    }
    w.doc.say(w.word(T::TrainWillis));
    w.worked(Worked::new(&whole, "", "", Printed::number(study.ratio, lang)).gives(ratio_key(t)));
    explain_ratio(w, (&whole_label(t), M::TrainRatio), t, &[]);
    names
}

/// The report's key of the train's ratio u_in,out.
fn ratio_key(t: &Train) -> Key {
    Key::of_scene(
        Symbol::GearRatio,
        format!("{}_{}", t.shafts[t.input], t.shafts[t.output]),
    )
}

/// u_in,out in label markup.
fn whole_label(t: &Train) -> String {
    format!("u_{{{}{}}}", t.shafts[t.input], t.shafts[t.output])
}

/// u_in,out in a formula.
fn whole(t: &Train) -> String {
    sym(&whole_label(t))
}

/// «где» under a speed's formula: the speeds of `shafts`.
fn explain_speeds(w: &mut Writer<'_, '_>, shafts: &[&str]) {
    let labels: Vec<String> = shafts.iter().map(|s| format!("n_{{{s}}}")).collect();
    let meaning = w.word(M::ShaftSpeed);
    let items: Vec<(&str, &str, &str)> = labels
        .iter()
        .map(|l| (l.as_str(), meaning, "rpm"))
        .collect();
    w.explain(&items);
}

/// n of shaft `s` in a formula.
fn speed(s: &str) -> String {
    sym(&format!("n_{{{s}}}"))
}

/// A differential's output speed from its two given ones: u_ab^(H) with the carrier stopped
/// from the teeth, the formula solved for the output, against Willis's relations.
fn differential_worked(w: &mut Writer<'_, '_>, study: &TrainStudy) {
    let t = &study.spec.train;
    let (Some(d), Some(h), Some(n_in)) = (t.differential(), t.carrier, study.spec.n_input) else {
        return;
    };
    let (Some(first), Some(last)) = (d.meshes.first(), d.meshes.last()) else {
        return;
    };
    let lang = w.lang;
    let rpm = unit(&unit_in("rpm", lang));
    let (a, b, hn) = (&t.shafts[d.a], &t.shafts[d.b], &t.shafts[h]);
    let u_label = format!(
        "u_{{{}{}}}^{{({hn})}}",
        t.wheels[first.0].name, t.wheels[last.1].name
    );
    let u = sym(&u_label);
    w.doc.say(w.word(T::TrainDifferential));
    let (symbolic, substituted) = chain(t, &d.meshes, lang);
    let relation = frac(
        &format!("{} - {}", speed(a), speed(hn)),
        &format!("{} - {}", speed(b), speed(hn)),
    );
    w.worked(Worked::new(
        &u,
        format!("{relation} = {symbolic}"),
        &substituted,
        Printed::number(d.u, lang),
    ));
    explain_ratio(w, (&u_label, M::StoppedRatio), t, &d.meshes);
    explain_speeds(w, &[a.as_str(), b.as_str(), hn.as_str()]);
    let [na, nb, nh] = d.omega.map(|x| factor(x * n_in, lang));
    let uu = factor(d.u, lang);
    let (out, symbolic, substituted, value) = if t.output == h {
        (
            hn,
            frac(
                &format!("{} - {u} {}", speed(a), speed(b)),
                &format!("1 - {u}"),
            ),
            frac(&format!("{na} - {uu} dot {nb}"), &format!("1 - {uu}")),
            d.omega[2],
        )
    } else if t.output == d.a {
        (
            a,
            format!("{} + {u} ({} - {})", speed(hn), speed(b), speed(hn)),
            format!("{nh} + {uu} dot ({nb} - {nh})"),
            d.omega[0],
        )
    } else {
        (
            b,
            format!(
                "{} + {}",
                speed(hn),
                frac(&format!("{} - {}", speed(a), speed(hn)), &u)
            ),
            format!("{nh} + {}", frac(&format!("{na} - {nh}"), &uu)),
            d.omega[1],
        )
    };
    w.worked(
        Worked::new(
            speed(out),
            &symbolic,
            &substituted,
            Printed::new(value * n_in, 5, format!(" {rpm}"), RPM, lang),
        )
        .gives(Key::of_scene(Symbol::AngularVelocity, out.as_str())),
    );
    w.doc.say(w.word(T::TrainWillis));
    let willis = study.willis[t.output] * n_in;
    w.worked(
        Worked::new(
            speed(out),
            "",
            "",
            Printed::new(willis, 5, format!(" {rpm}"), RPM, lang),
        )
        .gives(Key::of_scene(Symbol::AngularVelocity, out.as_str())),
    );
}

/// With the scene's input and required output speeds: the required ratio, the fixed-axis
/// stage it asks for (the other stages as chosen) and the output speed the chosen teeth give.
fn required_worked(w: &mut Writer<'_, '_>, study: &TrainStudy, stages: &[Stage], names: &[String]) {
    let (Some(n_in), Some(n_out)) = (study.spec.n_input, study.spec.n_output) else {
        return;
    };
    let lang = w.lang;
    let t = &study.spec.train;
    let (input, output) = (&t.shafts[t.input], &t.shafts[t.output]);
    let whole = whole(t);
    let wanted = |s: &str| format!("{s}^({})", sym("треб"));
    let want = (n_in / n_out).abs();
    w.doc.say(w.word(T::TrainRequired));
    let req = wanted(&format!("abs({whole})"));
    let speeds = frac(&speed(input), &wanted(&speed(output)));
    w.worked(Worked::new(
        &req,
        &speeds,
        frac(&n(n_in.abs(), lang), &n(n_out, lang)),
        Printed::number(want, lang),
    ));
    let ratios: Vec<f64> = stages.iter().map(|s| t.stage_ratio(s)).collect();
    let fixed = t.fixed_axis_mesh().map(|k| t.meshes[k]);
    let asked = stages.iter().position(|s| match (s, fixed) {
        (Stage::Mesh { driving, driven }, Some(m)) => {
            [(m.0, m.1), (m.1, m.0)].contains(&(*driving, *driven))
        }
        _ => false,
    });
    if let (Some(k), true) = (asked, stages.len() > 1) {
        let Stage::Mesh { driving, driven } = stages[k] else {
            return;
        };
        let others: Vec<&str> = names
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != k)
            .map(|(_, s)| s.as_str())
            .collect();
        let others_value: f64 = ratios
            .iter()
            .enumerate()
            .filter(|(i, _)| *i != k)
            .map(|(_, u)| u)
            .product();
        let symbolic = frac(&req, &format!("abs({})", others.join(" dot ")));
        let stage = format!("abs({})", names[k]);
        let substituted = frac(&n(want, lang), &n(others_value.abs(), lang));
        w.worked(Worked::new(
            wanted(&stage),
            &symbolic,
            &substituted,
            Printed::number(want / others_value.abs(), lang),
        ));
        w.doc.say(w.word(T::TrainChosen));
        let (zx, zy) = (t.wheels[driving].z, t.wheels[driven].z);
        w.worked(Worked::new(
            &stage,
            frac(&z(t, driven), &z(t, driving)),
            frac(&n(zy, lang), &n(zx, lang)),
            Printed::number(zy / zx, lang),
        ));
    }
    w.doc.say(w.word(T::TrainOutput));
    let out = n_in / study.ratio;
    let rpm = unit(&unit_in("rpm", lang));
    let substituted = frac(&n(n_in, lang), &factor(study.ratio, lang));
    let symbolic = frac(&speed(input), &whole);
    w.worked(
        Worked::new(
            speed(output),
            &symbolic,
            &substituted,
            Printed::new(out, 5, format!(" {rpm}"), RPM, lang),
        )
        .gives(Key::of_scene(Symbol::AngularVelocity, output.as_str())),
    );
    explain_speeds(w, &[output.as_str(), input.as_str()]);
    let delta = (out.abs() / n_out - 1.0) * 100.0;
    let target = wanted(&speed(output));
    w.worked(Worked::new(
        sym("δ"),
        format!(
            "{} dot 100 %",
            frac(&format!("abs({}) - {target}", speed(output)), &target)
        ),
        format!(
            "{} dot 100 %",
            frac(
                &format!("{} - {}", n(out.abs(), lang), n(n_out, lang)),
                &n(n_out, lang)
            )
        ),
        Printed::new(delta, 2, " %".into(), 0.01, lang),
    ));
    let deviation = w.word(M::SpeedDeviation);
    w.explain(&[("δ", deviation, "")]);
}
