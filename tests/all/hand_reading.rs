//! What a student hands in: `render` and `note` read every measured length as a hand
//! construction does (issue 44 §4), the exact check asked for by `--drafting 0`.

use crate::support;
use support::{scratch, tmm};

/// `render` and `note` read lengths as a hand construction does (0.5 mm) unless
/// `--drafting 0` asks for the exact check; `batch` keeps its answer key exact.
#[test]
fn render_and_note_read_as_a_hand_construction_by_default() {
    let dir = scratch("hand-reading");
    let sheet = |extra: &[&str], name: &str| {
        let out = dir.join(name);
        let mut args = vec![
            "render",
            "constructions/four-bar.toml",
            "--format",
            "svg",
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        let o = tmm(&args);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read_to_string(out.join("four-bar/kinematics.svg")).expect("the sheet")
    };
    let hand = sheet(&[], "hand");
    assert!(hand.contains("Длины считаны с чертежа с точностью 0,5 мм"));
    assert!(!hand.contains("Построения точные"));
    let exact = sheet(&["--drafting", "0"], "exact");
    assert!(exact.contains("Построения точные"));
    let help = |cmd: &str| String::from_utf8_lossy(&tmm(&[cmd, "--help"]).stdout).into_owned();
    assert!(help("note").contains("[default: 0.5]"), "{}", help("note"));
    assert!(
        help("report").contains("[default: 0]"),
        "{}",
        help("report")
    );
    let _ = std::fs::remove_dir_all(&dir);
}
