//! A description of the machine a report was measured on.

use std::fmt;

/// What a reader needs to interpret wall times: cores, OS, architecture, CPU model, the
/// compgeo version and whether the build was optimised.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Machine {
    /// Logical cores available to the process.
    pub cores: usize,
    /// Operating system (`std::env::consts::OS`), e.g. `"linux"`.
    pub os: String,
    /// CPU architecture (`std::env::consts::ARCH`), e.g. `"x86_64"`.
    pub arch: String,
    /// CPU model name, when the OS tells it (`/proc/cpuinfo` on Linux).
    pub cpu: Option<String>,
    /// The version of compgeo that measured.
    pub compgeo_version: String,
    /// `"release"` for an optimised build, `"debug"` otherwise (debug times are not
    /// representative).
    pub build: String,
}

impl Machine {
    /// Describes the machine this process runs on.
    pub fn current() -> Machine {
        Machine {
            cores: std::thread::available_parallelism().map_or(1, |c| c.get()),
            os: std::env::consts::OS.to_string(),
            arch: std::env::consts::ARCH.to_string(),
            cpu: cpu_model(),
            compgeo_version: env!("CARGO_PKG_VERSION").to_string(),
            build: if cfg!(debug_assertions) {
                "debug"
            } else {
                "release"
            }
            .to_string(),
        }
    }
}

impl fmt::Display for Machine {
    /// One line, e.g. `2 cores, linux x86_64, AMD EPYC 7B13, compgeo 0.1.0 (release)`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} cores, {} {}", self.cores, self.os, self.arch)?;
        if let Some(cpu) = &self.cpu {
            write!(f, ", {cpu}")?;
        }
        write!(f, ", compgeo {} ({})", self.compgeo_version, self.build)
    }
}

/// The first `model name` line of `/proc/cpuinfo`; `None` where there is no such file.
fn cpu_model() -> Option<String> {
    let info = std::fs::read_to_string("/proc/cpuinfo").ok()?;
    info.lines()
        .find(|l| l.starts_with("model name"))
        .and_then(|l| l.split_once(':'))
        .map(|(_, v)| v.trim().to_string())
        .filter(|v| !v.is_empty())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn current_machine_has_cores_and_names() {
        let m = Machine::current();
        assert!(m.cores >= 1);
        assert!(!m.os.is_empty() && !m.arch.is_empty());
        assert_eq!(m.compgeo_version, env!("CARGO_PKG_VERSION"));
        let line = m.to_string();
        assert!(line.starts_with(&format!("{} cores, ", m.cores)), "{line}");
    }
}
