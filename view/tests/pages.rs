//! Pages written to disk: the bytes reported, the embedded document read back, errors naming
//! the path or the field.

use mit_star_view::{
    LinkView, MotionView, RobotView, SceneView, ViewDocument, ViewError, ViewKind, ViewLimits,
};

/// A two-link arm moving over `frames` frames.
fn arm(frames: usize) -> ViewDocument {
    let mut doc = ViewDocument::new(ViewKind::Arm, "two links </script> <!-- here");
    doc.robot = Some(RobotView {
        name: "toy".into(),
        links: ["base", "hand"]
            .iter()
            .map(|name| LinkView {
                name: (*name).into(),
                spheres: vec![0.0, 0.0, 0.1, 0.05],
                meshes: Vec::new(),
            })
            .collect(),
        hand: 1,
    });
    doc.scene = SceneView::default();
    let mut poses = Vec::new();
    for f in 0..frames {
        for l in 0..2 {
            poses.extend_from_slice(&[f as f32 * 0.01, 0.0, l as f32 * 0.2, 0.0, 0.0, 0.0, 1.0]);
        }
    }
    doc.motions.push(MotionView {
        label: "plan".into(),
        joint_names: vec!["j1".into()],
        frames,
        joints: (0..frames).map(|f| f as f32).collect(),
        poses,
        times: Some((0..frames).map(|f| f as f64 * 0.1).collect()),
        waypoints: vec![0, frames - 1],
        colliding: vec![frames / 2],
        mover_positions: Vec::new(),
    });
    doc
}

/// The JSON the page embeds.
fn embedded(html: &str) -> serde_json::Value {
    let open = "<script type=\"application/json\" id=\"mit-star-view-data\">";
    let start = html.find(open).expect("the data element") + open.len();
    let end = start + html[start..].find("</script>").expect("its end");
    serde_json::from_str(&html[start..end]).expect("the embedded JSON parses")
}

#[test]
fn a_written_page_holds_the_document_and_reports_its_size() {
    let dir = std::env::temp_dir().join(format!("view-pages-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("arm.html");
    let limits = ViewLimits {
        frames_per_motion: 11,
        ..ViewLimits::default()
    };
    let bytes = arm(101).write_html(&path, limits).unwrap();
    let html = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(bytes, html.len() as u64);
    let json = embedded(&html);
    assert_eq!(json["title"], "two links </script> <!-- here");
    assert_eq!(json["motions"][0]["frames"], 11);
    assert_eq!(json["motions"][0]["times"][10], 10.0);
    assert_eq!(json["motions"][0]["colliding"][0], 5);
    assert!(
        json["notes"][0]
            .as_str()
            .unwrap()
            .contains("101 frames, 11 drawn")
    );
    assert!(
        html.contains("The MIT License"),
        "three.js's licence travels with it"
    );
}

#[test]
fn an_unwritable_path_is_named() {
    let path = std::env::temp_dir()
        .join("view-no-such-folder-7f3a")
        .join("page.html");
    let error = arm(3).write_html(&path, ViewLimits::default()).unwrap_err();
    assert!(matches!(error, ViewError::Io { .. }));
    assert!(
        error.to_string().contains("view-no-such-folder-7f3a"),
        "{error}"
    );
}

#[test]
fn an_inconsistent_document_makes_no_page() {
    let mut doc = arm(4);
    doc.motions[0].poses.pop();
    let error = doc.to_html(ViewLimits::default()).unwrap_err();
    assert!(
        error.to_string().contains("motions[0] (plan).poses"),
        "{error}"
    );
}
