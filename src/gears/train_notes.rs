//! The notes of a train study: the inversion table, the mobility, the ratio, a differential's
//! formula, the module a non-coaxial stage is drawn at (what the source leaves out), what the
//! source prints against what the teeth give, the required ratio and the best teeth, the
//! neighbour and assembly conditions.

use super::train::{best_pairs, Stage, Train};
use super::train_layout::teeth_across;
use super::train_study::{TrainSeed, TrainStudy};

/// A number for the notes.
fn num(x: f64, sig: usize) -> String {
    crate::scale::format_sig(x, sig, crate::scale::Lang::En)
}

/// One mesh's ratio with the carrier stopped, as the notes write it: `(−30/20)`.
fn mesh_text(t: &Train, x: usize, y: usize) -> String {
    let sign = if t.mesh_ratio(x, y) < 0.0 { "−" } else { "" };
    format!("({sign}{}/{})", t.wheels[y].z, t.wheels[x].z)
}

/// The teeth across mesh (x, y)'s centre distance, as the notes write them: `z1 + z2`, or
/// `z5 − z4` for a ring 5.
fn across_text(t: &Train, x: usize, y: usize) -> String {
    let (wx, wy) = (&t.wheels[x], &t.wheels[y]);
    match (wx.internal, wy.internal) {
        (true, _) => format!("z{} − z{}", wx.name, wy.name),
        (_, true) => format!("z{} − z{}", wy.name, wx.name),
        _ => format!("z{} + z{}", wx.name, wy.name),
    }
}

/// What a printed ratio asks of the one planetary stage: its wheels a and f, the u_af^(H)
/// the printed ratio needs with the other stages as their teeth give, and the u_af^(H) the
/// teeth give.
#[derive(Debug, Clone, PartialEq)]
pub struct SeedStage {
    /// The central wheel a's name.
    pub a: String,
    /// The fixed wheel f's name.
    pub f: String,
    /// u_af^(H) the printed ratio needs.
    pub needed: f64,
    /// u_af^(H) of the teeth.
    pub teeth: f64,
}

impl TrainStudy {
    /// The notes: the inversion table, the mobility, the ratio, the differential's formula,
    /// the closed stages, the source's printed values, the required ratio and the best tooth
    /// numbers of the first mesh for it, the neighbour and assembly conditions.
    pub fn notes(&self) -> Vec<String> {
        let mut out = vec![];
        out.extend(self.inversion_note());
        out.push(self.mobility_note());
        out.push(format!(
            "train: u = {} by Willis{}; the output turns {} the input",
            num(self.ratio, 7),
            self.formula.map_or(String::new(), |s| format!(
                ", {} by {}",
                num(s, 7),
                if self.spec.train.second.is_some() {
                    "Willis's formula of the differential"
                } else {
                    "the stages"
                }
            )),
            if self.ratio < 0.0 { "against" } else { "with" }
        ));
        out.extend(self.differential_note());
        out.extend(self.closing_notes());
        out.extend(self.seed_notes());
        out.extend(self.required_notes());
        out.extend(self.satellite_notes());
        out
    }

    /// The inversion table (seed 002 Table 2.1).
    fn inversion_note(&self) -> Option<String> {
        let n_in = self.spec.n_input.unwrap_or(1.0);
        let inv = self.spec.train.inversion().ok()?;
        let cells: Vec<String> = inv
            .iter()
            .map(|(s, w, r)| format!("{s}: {} → {}", num(w * n_in, 6), num(r * n_in, 6)))
            .collect();
        Some(format!(
            "train: inversion (Willis): n before → n − n_H after stopping the carrier{}: {}",
            if self.spec.n_input.is_some() {
                ", rpm"
            } else {
                " (per unit input)"
            },
            cells.join("; ")
        ))
    }

    /// W = 3n − 2p₅ − p₄, with a differential's two inputs.
    fn mobility_note(&self) -> String {
        let t = &self.spec.train;
        let n_in = self.spec.n_input.unwrap_or(1.0);
        let m = t.mobility();
        format!(
            "train: W = 3n − 2p5 − p4 = 3·{} − 2·{} − {} = {}{}",
            m.n,
            m.p5,
            m.p4,
            m.w(),
            match t.second {
                Some((k, w)) => format!(
                    " (a differential: the inputs {} and {}, n = {} and {} rpm)",
                    t.shafts[t.input],
                    t.shafts[k],
                    num(n_in, 6),
                    num(w * n_in, 6)
                ),
                None => String::new(),
            }
        )
    }

    /// A differential by Willis's formula: u_ab^(H) from the teeth, the output's speed.
    fn differential_note(&self) -> Option<String> {
        let t = &self.spec.train;
        let d = t.differential()?;
        let h = t.carrier?;
        let n_in = self.spec.n_input.unwrap_or(1.0);
        let (a, b, hn) = (&t.shafts[d.a], &t.shafts[d.b], &t.shafts[h]);
        let teeth: Vec<String> = d.meshes.iter().map(|&(x, y)| mesh_text(t, x, y)).collect();
        let solved = if t.output == h {
            format!("n{hn} = (n{a} − u·n{b})/(1 − u)")
        } else if t.output == d.a {
            format!("n{a} = n{hn} + u·(n{b} − n{hn})")
        } else {
            format!("n{b} = n{hn} + (n{a} − n{hn})/u")
        };
        let out = [d.a, d.b, h].iter().position(|&k| k == t.output)?;
        Some(format!(
            "train: a differential by Willis's formula: u = u{a}{b}^({hn}) = (n{a} − n{hn})/(n{b} − n{hn}) = {} = {}; {solved} = {} rpm (n{a} = {}, n{b} = {}, n{hn} = {} rpm)",
            teeth.join("·"),
            num(d.u, 6),
            num(d.omega[out] * n_in, 6),
            num(d.omega[0] * n_in, 6),
            num(d.omega[1] * n_in, 6),
            num(d.omega[2] * n_in, 6),
        ))
    }

    /// Each mesh taken at the module that closes the carrier's arm: the datum the source
    /// leaves out.
    fn closing_notes(&self) -> Vec<String> {
        let t = &self.spec.train;
        let m = t.module * 1e3;
        self.closings
            .iter()
            .map(|c| {
                let ((s, w), (sa, wa)) = (c.mesh, c.arm_mesh);
                let (name, arm_name) = (
                    format!("{}–{}", t.wheels[s].name, t.wheels[w].name),
                    format!("{}–{}", t.wheels[wa].name, t.wheels[sa].name),
                );
                format!(
                    "train: the source gives no module of the mesh {name}: at the train's m = {} mm the tooth sums do not close — the mesh {arm_name} sets the carrier's arm a = m({})/2 = {} mm, the mesh {name} reaches m({})/2 = {} mm — so the train as given cannot be assembled; Willis's relations use the teeth only, and the velocity triangles take the mesh {name} at m′ = 2a/({}) = {} mm (assumed: the module that brings wheel {} onto the carrier's axis)",
                    num(m, 5),
                    across_text(t, wa, sa),
                    num(c.arm * 1e3, 6),
                    across_text(t, s, w),
                    num(m * teeth_across(t, s, w) / 2.0, 6),
                    across_text(t, s, w),
                    num(c.module * 1e3, 6),
                    t.wheels[w].name,
                )
            })
            .collect()
    }

    /// What a printed ratio needs of the train's one planetary stage, the other stages as
    /// their teeth give; `None` without a printed ratio or such a stage.
    pub fn seed_stage(&self) -> Option<SeedStage> {
        let t = &self.spec.train;
        let printed = self.spec.seed.u?;
        let stages = t.stages()?;
        let mut planetary = stages.iter().filter_map(|s| match s {
            Stage::Planetary { meshes } => Some(meshes),
            Stage::Mesh { .. } => None,
        });
        let meshes = planetary.next()?;
        if planetary.next().is_some() {
            return None;
        }
        let others: f64 = stages
            .iter()
            .filter(|s| matches!(s, Stage::Mesh { .. }))
            .map(|s| t.stage_ratio(s))
            .product();
        let teeth: f64 = meshes.iter().map(|&(x, y)| t.mesh_ratio(x, y)).product();
        let (first, last) = (meshes.first()?, meshes.last()?);
        Some(SeedStage {
            a: t.wheels[first.0].name.clone(),
            f: t.wheels[last.1].name.clone(),
            needed: 1.0 - printed / others,
            teeth,
        })
    }

    /// The source's printed mobility and ratio against the train's.
    fn seed_notes(&self) -> Vec<String> {
        let t = &self.spec.train;
        let seed = self.spec.seed;
        let mut out = Vec::new();
        let m = t.mobility();
        if let Some(w) = seed.w {
            out.push(if w == m.w() {
                format!("train: the seed's W = {w} reproduced")
            } else {
                format!(
                    "train: erratum: the seed prints W = {w}; W = 3·{} − 2·{} − {} = {}",
                    m.n,
                    m.p5,
                    m.p4,
                    m.w()
                )
            });
        }
        let Some(u) = seed.u else {
            return out;
        };
        let name = format!("u_{}_{}", t.shafts[t.input], t.shafts[t.output]);
        if TrainSeed::reproduces(u, self.ratio) {
            out.push(format!(
                "train: the seed's {name} = {} reproduced (Willis {})",
                num(u, 6),
                num(self.ratio, 7)
            ));
            return out;
        }
        let why = self.seed_stage().map_or(String::new(), |s| {
            format!(
                "; with the other stages as their teeth give, {} needs u_{}{}^(H) = {} of the planetary stage, whose teeth give {}",
                num(u, 6),
                s.a,
                s.f,
                num(s.needed, 6),
                num(s.teeth, 6)
            )
        });
        out.push(format!(
            "train: erratum: the seed prints {name} = {}; Willis's relations give {}{}, the triangles {}{why}",
            num(u, 6),
            num(self.ratio, 7),
            self.formula
                .map_or(String::new(), |f| format!(", the formula {}", num(f, 7))),
            num(self.triangles.ratio, 7),
        ));
        out
    }

    /// With the input's and the required output speed: the required ratio, the first
    /// fixed-axis mesh's teeth for it.
    fn required_notes(&self) -> Vec<String> {
        let t = &self.spec.train;
        let (Some(n1), Some(n_out)) = (self.spec.n_input, self.spec.n_output) else {
            return Vec::new();
        };
        let required = (n1 / n_out).abs();
        let mut out = vec![format!(
            "train: required |u| = {}/{} = {}; the tooth numbers give {} (n_out = {} rpm, {} %)",
            num(n1.abs(), 6),
            num(n_out, 6),
            num(required, 6),
            num(self.ratio.abs(), 6),
            num(n1.abs() / self.ratio.abs(), 6),
            num((self.ratio.abs() / required - 1.0) * 100.0, 3)
        )];
        if let Some(m) = t.fixed_axis_mesh().map(|k| t.meshes[k]) {
            let (a, b) = (&t.wheels[m.0], &t.wheels[m.1]);
            let now = b.z / a.z;
            let want = now * required / self.ratio.abs();
            let list: Vec<String> = best_pairs(want, 17, 40, 4)
                .iter()
                .map(|(z1, z2, e)| {
                    format!(
                        "{z2}/{z1} ({} %, n_out = {} rpm)",
                        num(e * 100.0, 3),
                        num(n_out / (1.0 + e), 6)
                    )
                })
                .collect();
            out.push(format!(
                "train: mesh {}–{} needs z{}/z{} = {}: best {} (now {}/{} = {})",
                a.name,
                b.name,
                b.name,
                a.name,
                num(want, 6),
                list.join(", "),
                b.z,
                a.z,
                num(now, 5)
            ));
        }
        out
    }

    /// With the number of satellites: the neighbour and the assembly conditions.
    fn satellite_notes(&self) -> Vec<String> {
        let t = &self.drawn;
        let Some(k) = self.spec.satellites else {
            return Vec::new();
        };
        let mut out = Vec::new();
        for (w, chord, da) in t.neighbour(k).unwrap_or_default() {
            out.push(format!(
                "train: neighbour condition, k = {k}: 2·a·sin(π/k) = {} mm {} d_a{} = {} mm",
                num(chord * 1e3, 5),
                if chord > da { ">" } else { "≤ (fails:)" },
                t.wheels[w].name,
                num(da * 1e3, 5)
            ));
        }
        let Some(a) = t.assembly(k) else {
            return out;
        };
        let z = &t.wheels[a.central];
        let b = t.fixed.map_or("", |f| t.shafts[f].as_str());
        let frac = |(n, d): (i128, i128)| match (n, d) {
            (n, 1) if n >= 0 => n.to_string(),
            (n, 1) => format!("(−{})", -n),
            (n, d) if n >= 0 => format!("{n}/{d}"),
            (n, d) => format!("(−{}/{d})", -n),
        };
        let value = frac(a.value);
        let textbook = match a.p {
            Some(p) => format!("whole for p = {p}"),
            None => "never whole".to_string(),
        };
        let block = a.block.map_or(String::new(), |v| {
            format!(
                "; for identical blocks, z{}·u{}H·(z_f/gcd(z_g, z_f))/k = {}",
                z.name,
                z.name,
                frac(v)
            )
        });
        let verdict = if a.fits() {
            format!("the {k} satellites assemble spaced equally")
        } else {
            let fit: Vec<String> = (2..=8)
                .filter(|&j| t.admits(j))
                .map(|j| j.to_string())
                .collect();
            format!(
                "fails: {k} satellites cannot be spaced equally; k = {} can (assembly and neighbour)",
                fit.join(", ")
            )
        };
        out.push(format!(
            "train: assembly condition, k = {k}: z{}·u{}H^({b})/k = {value}, (1 + kp)·{value} {textbook} (the textbook's){block}: {verdict}",
            z.name, z.name
        ));
        out
    }
}
