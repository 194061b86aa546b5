//! [`MachineInfo`]: the host, its CPU and the date, as benchmark logs record them.

use std::time::{SystemTime, UNIX_EPOCH};

use serde::Serialize;

/// Where and when an experiment ran.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct MachineInfo {
    /// The host's name (no whitespace; `UNKNOWN` if it cannot be read).
    pub hostname: String,
    /// The CPU model and core count, from `/proc/cpuinfo` where available.
    pub cpu: String,
    /// Hardware threads available to this process.
    pub available_threads: usize,
}

impl MachineInfo {
    /// Reads the host's name and CPU description.
    pub fn detect() -> Self {
        let hostname = ["/proc/sys/kernel/hostname", "/etc/hostname"]
            .iter()
            .filter_map(|p| std::fs::read_to_string(p).ok())
            .map(|s| s.trim().to_owned())
            .find(|s| !s.is_empty())
            .or_else(|| std::env::var("HOSTNAME").ok())
            .map(|s| s.split_whitespace().collect::<Vec<_>>().join("-"))
            .filter(|s| !s.is_empty())
            .unwrap_or_else(|| "UNKNOWN".to_owned());
        let available_threads = std::thread::available_parallelism().map_or(1, |n| n.get());
        let cpu = match std::fs::read_to_string("/proc/cpuinfo") {
            Ok(text) => describe_cpu(&text, available_threads),
            Err(_) => format!(
                "{} {}, {available_threads} hardware threads",
                std::env::consts::ARCH,
                std::env::consts::OS
            ),
        };
        Self {
            hostname,
            cpu,
            available_threads,
        }
    }
}

/// `model name`, processor count and clock from the text of `/proc/cpuinfo`.
fn describe_cpu(cpuinfo: &str, available: usize) -> String {
    let field = |name: &str| {
        cpuinfo.lines().find_map(|l| {
            let (k, v) = l.split_once(':')?;
            (k.trim() == name).then(|| v.trim().to_owned())
        })
    };
    let processors = cpuinfo
        .lines()
        .filter(|l| l.split(':').next().is_some_and(|k| k.trim() == "processor"))
        .count();
    let model = field("model name").unwrap_or_else(|| std::env::consts::ARCH.to_owned());
    let mut text = format!("{model}, {processors} logical processors ({available} available)");
    if let Some(mhz) = field("cpu MHz") {
        text.push_str(&format!(", {mhz} MHz"));
    }
    text
}

/// A time as OMPL writes it (`to_iso_extended_string`): `2025-03-01T14:05:09.123456`, in UTC.
///
/// ```
/// use std::time::{Duration, UNIX_EPOCH};
/// let t = UNIX_EPOCH + Duration::from_micros(951_782_400_000_001); // 2000-02-29
/// assert_eq!(mit_star_benches::iso_timestamp(t), "2000-02-29T00:00:00.000001");
/// ```
pub fn iso_timestamp(time: SystemTime) -> String {
    let since = time.duration_since(UNIX_EPOCH).unwrap_or_default();
    let seconds = since.as_secs();
    let (days, rest) = (seconds / 86_400, seconds % 86_400);
    let (year, month, day) = civil_from_days(days as i64);
    format!(
        "{year:04}-{month:02}-{day:02}T{:02}:{:02}:{:02}.{:06}",
        rest / 3600,
        rest % 3600 / 60,
        rest % 60,
        since.subsec_micros()
    )
}

/// The proleptic Gregorian date of a day count since 1970-01-01 (Howard Hinnant's algorithm).
fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let month = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let year = yoe + era * 400 + i64::from(month <= 2);
    (year, month, day)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    #[test]
    fn dates() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(civil_from_days(59), (1970, 3, 1));
        assert_eq!(civil_from_days(19_723), (2024, 1, 1));
        assert_eq!(civil_from_days(11_016), (2000, 2, 29));
        let t = UNIX_EPOCH + Duration::new(1_700_000_000, 5_000);
        assert_eq!(iso_timestamp(t), "2023-11-14T22:13:20.000005");
    }

    #[test]
    fn cpu_description() {
        let text = "processor\t: 0\nmodel name\t: Test CPU\ncpu MHz\t\t: 3900.0\n\nprocessor\t: 1\nmodel name\t: Test CPU\n";
        assert_eq!(
            describe_cpu(text, 2),
            "Test CPU, 2 logical processors (2 available), 3900.0 MHz"
        );
        let m = MachineInfo::detect();
        assert!(!m.hostname.is_empty() && !m.hostname.contains(' '));
        assert!(m.available_threads >= 1);
    }
}
