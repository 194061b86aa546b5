//! Extreme values at every command-line entry point: each flag of `plan` and `bench`, each
//! field of an experiment file, each `--set` override. Every one is a clear error with exit
//! code 2 or a correct run — never a panic (101), an abort (134) or a silent exit 0 with
//! errored runs.

use std::process::Command;

const EXTREMES: [&str; 14] = [
    "0",
    "-0",
    "-1",
    "1e308",
    "-1e308",
    "5e-324",
    "nan",
    "inf",
    "-inf",
    "18446744073709551615",
    "18446744073709551616",
    "-9223372036854775808",
    "",
    "x",
];

fn run(args: &[&str]) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_mit-star"))
        .args(args)
        .output()
        .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (out.status.code(), stderr)
}

fn acceptable(args: &[&str], (code, stderr): &(Option<i32>, String)) {
    assert!(
        matches!(code, Some(0 | 2 | 3)),
        "{args:?}: exit {code:?}: {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    if *code == Some(2) {
        assert!(stderr.starts_with("error:"), "{args:?}: {stderr}");
        assert!(
            !stderr.contains("000000000000000000000"),
            "{args:?}: {stderr}"
        );
    }
}

#[test]
fn plan_flags_take_any_value() {
    let dir = std::env::temp_dir().join(format!("mit-star-extreme-plan-{}", std::process::id()));
    let output = dir.display().to_string();
    for flag in ["--time", "--dim", "--seed", "--instance", "--resolution"] {
        for value in EXTREMES {
            let mut args = vec![
                "plan",
                "--problem",
                "wall-gap",
                "--no-picture",
                "--output",
                &output,
            ];
            if flag != "--time" {
                args.extend(["--time", "0.05"]);
            }
            let assignment = format!("{flag}={value}");
            args.push(&assignment);
            let result = run(&args);
            acceptable(&args, &result);
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn set_overrides_take_any_value() {
    for key in [
        "batch_size",
        "rewire_factor",
        "bridge_checks",
        "gaussian_std_fraction",
        "sparse_initial_steps",
        "sparse_factor",
        "sparse_min_steps",
        "pruning",
        "connection",
    ] {
        for value in EXTREMES {
            let assignment = format!("{key}={value}");
            let args = [
                "plan",
                "--problem",
                "wall-gap",
                "--no-picture",
                "--time",
                "0.03",
                "--set",
                &assignment,
            ];
            let result = run(&args);
            acceptable(&args, &result);
        }
    }
}

#[test]
fn bench_flags_and_experiment_fields_take_any_value() {
    let dir = std::env::temp_dir().join(format!("mit-star-extreme-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let output = dir.join("out").display().to_string();
    for (flag, value) in EXTREMES.iter().flat_map(|v| {
        [
            "--runs",
            "--time",
            "--dims",
            "--threads",
            "--seed",
            "--instances",
        ]
        .map(|f| (f, *v))
    }) {
        let assignment = format!("{flag}={value}");
        let mut args = vec![
            "bench",
            "--planners",
            "mit-star",
            "--problem",
            "wall-gap",
            "--no-plots",
            "-q",
            "--output",
            &output,
        ];
        for (f, default) in [("--runs", "1"), ("--time", "0.02"), ("--dims", "2")] {
            if f != flag {
                args.extend([f, default]);
            }
        }
        args.push(&assignment);
        let result = run(&args);
        acceptable(&args, &result);
        let _ = std::fs::remove_dir_all(&output);
    }
    let template = "name = \"e\"\nruns = RUNS\nseed = SEED\nconfidence = CONF\nplanners = [\"mit-star\"]\n\
                    [[problems]]\nname = \"wall-gap\"\ndimensions = [DIM]\ntime = TIME\n";
    let file = dir.join("e.toml");
    for field in ["RUNS", "SEED", "CONF", "DIM", "TIME"] {
        for value in EXTREMES.iter().filter(|v| !v.is_empty() && **v != "x") {
            let text = template
                .replace(field, value)
                .replace("RUNS", "1")
                .replace("SEED", "0")
                .replace("CONF", "0.9")
                .replace("DIM", "2")
                .replace("TIME", "0.02");
            std::fs::write(&file, &text).unwrap();
            let args = [
                "bench",
                file.to_str().unwrap(),
                "--no-plots",
                "-q",
                "--output",
                &output,
            ];
            let result = run(&args);
            acceptable(&args, &result);
            let _ = std::fs::remove_dir_all(&output);
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}
