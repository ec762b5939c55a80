//! One declaration per algorithm: everything that names an algorithm or states its bound
//! agrees with its [`Declaration`], and a change in one place only fails here.
//!
//! - the crate docs' algorithm table is [`table`] (set `COMPGEO_UPDATE_DOCS=1` to rewrite
//!   `src/lib.rs` from the declarations after changing one);
//! - every declared item exists in its declared file, and its rustdoc states the declared
//!   time and space under `# Complexity`;
//! - every catalog entry measures a declared claim, with the claim's bound and operation, and
//!   every claim is measured once;
//! - every declared algorithm has a counted operation and a measured claim, unless it is
//!   exempt (`UNMEASURED`, empty, each exemption with its reason), and the README and
//!   the crate docs say how many are measured;
//! - every algorithm family's enum parses and prints the declared names, and the command
//!   line's `--help` lists them with their bounds.

use compgeo::complexity::{catalog, declarations, table, Declaration};
use std::collections::{HashMap, HashSet};
use std::fs;
use std::path::Path;

/// The markers around the generated table in `src/lib.rs`.
const BEGIN: &str = "<!-- algorithms -->";
const END: &str = "<!-- /algorithms -->";

/// The crate root, where `src/` and `Cargo.toml` are.
fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The text between the markers of `//!` docs, without the comment prefix.
fn between_markers(source: &str) -> Option<String> {
    let lines: Vec<&str> = source.lines().collect();
    let start = lines.iter().position(|l| l.contains(BEGIN))?;
    let end = lines.iter().position(|l| l.contains(END))?;
    Some(
        lines[start + 1..end]
            .iter()
            .map(|l| {
                let l = l.strip_prefix("//!").unwrap_or(l);
                format!("{}\n", l.strip_prefix(' ').unwrap_or(l))
            })
            .collect(),
    )
}

#[test]
fn the_crate_docs_show_the_declared_table() {
    let path = root().join("src/lib.rs");
    let source = fs::read_to_string(&path).unwrap();
    let shown = between_markers(&source).expect("src/lib.rs has the table markers");
    let declared = table();
    if shown != declared && std::env::var_os("COMPGEO_UPDATE_DOCS").is_some() {
        let lines: Vec<&str> = source.lines().collect();
        let start = lines.iter().position(|l| l.contains(BEGIN)).unwrap();
        let end = lines.iter().position(|l| l.contains(END)).unwrap();
        let mut out: Vec<String> = lines[..=start].iter().map(|l| l.to_string()).collect();
        out.extend(declared.lines().map(|l| format!("//! {l}")));
        out.extend(lines[end..].iter().map(|l| l.to_string()));
        fs::write(&path, out.join("\n") + "\n").unwrap();
        return;
    }
    assert_eq!(
        shown, declared,
        "src/lib.rs's algorithm table differs from the declarations; \
         rerun with COMPGEO_UPDATE_DOCS=1 to regenerate it"
    );
}

#[test]
fn names_are_kebab_case_and_ids_unique() {
    let mut ids = HashSet::new();
    for d in declarations() {
        for word in [d.problem, d.name] {
            assert!(
                !word.is_empty()
                    && word
                        .chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'),
                "{word:?} is not kebab-case"
            );
        }
        assert!(ids.insert(d.id()), "{} is declared twice", d.id());
        assert!(!d.time.is_empty() && !d.space.is_empty() && !d.summary.is_empty());
        assert!(
            d.source.starts_with('[') && d.source.ends_with(']'),
            "{}: cite the source as [KEY, §n]",
            d.id()
        );
        assert!(
            d.claims.is_empty() || d.operation.is_some(),
            "{}: a measured algorithm declares its counted operation",
            d.id()
        );
        let mut inputs = HashSet::new();
        for c in d.claims {
            assert!(
                inputs.insert(c.input),
                "{} claims {} twice",
                d.id(),
                c.input
            );
        }
    }
}

/// The doc comment (without `///`) of the item declared on line `at`, skipping attributes.
fn doc_before(lines: &[&str], at: usize) -> String {
    let mut doc = Vec::new();
    for line in lines[..at].iter().rev() {
        let t = line.trim_start();
        if let Some(text) = t.strip_prefix("///") {
            doc.push(text.strip_prefix(' ').unwrap_or(text));
        } else if t.starts_with("#[") || t.is_empty() && doc.is_empty() {
            continue;
        } else {
            break;
        }
    }
    doc.reverse();
    doc.join("\n")
}

/// The `# Complexity` section of a doc comment, up to the next heading or example.
fn complexity_section(doc: &str) -> Option<String> {
    let start = doc.find("# Complexity")?;
    let rest = &doc[start + "# Complexity".len()..];
    let end = [rest.find("\n# "), rest.find("\n```")]
        .into_iter()
        .flatten()
        .min()
        .unwrap_or(rest.len());
    // Words wrap across lines; compare with single spaces.
    Some(rest[..end].split_whitespace().collect::<Vec<_>>().join(" "))
}

/// Every item of `d` whose docs could state its bound: `name` and `name_with`.
fn documented_items(d: &Declaration) -> (String, Vec<String>) {
    let source = fs::read_to_string(root().join(d.file))
        .unwrap_or_else(|e| panic!("{}: declared file {}: {e}", d.id(), d.file));
    let item = d.function.rsplit("::").next().unwrap();
    let lines: Vec<&str> = source.lines().collect();
    let mut docs = Vec::new();
    for name in [item.to_string(), format!("{item}_with")] {
        for (k, line) in lines.iter().enumerate() {
            let t = line.trim_start();
            let declares = ["pub fn ", "pub struct "].iter().any(|kw| {
                t.strip_prefix(kw).is_some_and(|rest| {
                    rest.strip_prefix(name.as_str())
                        .is_some_and(|after| after.starts_with(['(', '<', ' ', '{']))
                })
            });
            if declares {
                docs.push(doc_before(&lines, k));
            }
        }
    }
    (item.to_string(), docs)
}

#[test]
fn every_declared_item_exists_and_states_its_bound() {
    let squash = |s: &str| s.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut wrong = Vec::new();
    for d in declarations() {
        let (item, docs) = documented_items(d);
        if docs.is_empty() {
            wrong.push(format!(
                "{}: no `pub fn {item}` in {} (declared as {})",
                d.id(),
                d.file,
                d.function
            ));
            continue;
        }
        let states = docs
            .iter()
            .filter_map(|doc| complexity_section(doc))
            .any(|c| c.contains(&squash(d.time)) && c.contains(&squash(d.space)));
        if !states {
            wrong.push(format!(
                "{}: the `# Complexity` docs of {} (or its `_with` form) in {} do not state the \
                 declared time {:?} and space {:?}",
                d.id(),
                d.function,
                d.file,
                d.time,
                d.space
            ));
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn every_catalog_entry_measures_a_declared_claim_and_every_claim_is_measured() {
    let declared: HashMap<String, &Declaration> =
        declarations().into_iter().map(|d| (d.id(), d)).collect();
    let mut measured = HashSet::new();
    for e in catalog() {
        let d = declared
            .get(&e.info.id)
            .unwrap_or_else(|| panic!("catalog entry {} has no declaration", e.info.key()));
        let claim = d
            .claim(&e.info.input)
            .unwrap_or_else(|| panic!("{} declares no claim on {}", d.id(), e.info.input));
        assert_eq!(
            (claim.bound, claim.operation),
            (e.info.bound, e.info.operation),
            "{}",
            e.info.key()
        );
        assert!(
            measured.insert(e.info.key()),
            "{} is measured twice",
            e.info.key()
        );
    }
    for d in declarations() {
        for c in d.claims {
            let key = format!("{}/{}", d.id(), c.input);
            assert!(
                measured.contains(&key),
                "the claim {key} is not in the catalog"
            );
        }
    }
}

/// Declared algorithms that the catalog may leave unmeasured, each with the reason. Every
/// other declaration claims at least one growth, which the test above finds in the catalog.
/// Keep this list empty unless an algorithm's input cannot grow (and then say so).
const UNMEASURED: &[(&str, &str)] = &[];

#[test]
fn every_declared_algorithm_is_measured_unless_exempt_with_a_reason() {
    let declared: HashSet<String> = declarations().iter().map(|d| d.id()).collect();
    for (id, reason) in UNMEASURED {
        assert!(declared.contains(*id), "exemption for undeclared {id}");
        assert!(
            reason.split_whitespace().count() >= 3,
            "{id}: an exemption needs a reason a reviewer can check, got {reason:?}"
        );
    }
    let measured: HashSet<String> = catalog().iter().map(|e| e.info.id.clone()).collect();
    let mut missing = Vec::new();
    for d in declarations() {
        let exempt = UNMEASURED.iter().any(|(id, _)| *id == d.id());
        if d.operation.is_none() {
            missing.push(format!("{}: no counter variant (operation: None)", d.id()));
        } else if d.claims.is_empty() && !exempt {
            missing.push(format!("{}: claims nothing the catalog measures", d.id()));
        } else if !exempt && !measured.contains(&d.id()) {
            missing.push(format!("{}: no catalog entry", d.id()));
        } else if exempt && !d.claims.is_empty() {
            missing.push(format!("{}: exempt, yet it claims a growth", d.id()));
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
}

/// The sentence the README and the crate docs use to say how much the report measures.
fn measured_sentence() -> String {
    let entries = catalog();
    let ids: HashSet<&str> = entries.iter().map(|e| e.info.id.as_str()).collect();
    format!(
        "measures all {} declared algorithms in {} catalog entries",
        ids.len(),
        entries.len()
    )
}

/// `text` with `//!` prefixes removed and runs of whitespace made one space, so a sentence
/// may wrap anywhere.
fn flattened(text: &str) -> String {
    text.lines()
        .map(|l| l.trim_start().strip_prefix("//!").unwrap_or(l))
        .collect::<Vec<_>>()
        .join(" ")
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn readme_and_crate_docs_state_the_number_of_measured_algorithms() {
    let measured: HashSet<String> = catalog().iter().map(|e| e.info.id.clone()).collect();
    assert_eq!(
        measured.len(),
        declarations().len() - UNMEASURED.len(),
        "every declared algorithm but the exempt ones is measured"
    );
    let sentence = measured_sentence();
    for file in ["README.md", "src/lib.rs"] {
        let text = flattened(&fs::read_to_string(root().join(file)).unwrap());
        assert!(
            text.contains(&sentence),
            "{file} should say \"{sentence}\" (the report's results.json gives the same \
             number as measured_algorithms)"
        );
    }
}

/// Every family: each algorithm is in the registry ([`declarations`]) under the family's
/// problem, parses back from its name, prints as its name; an unknown name lists them all.
macro_rules! check_family {
    ($family:ty, $problem:literal) => {{
        let registered: HashSet<String> = declarations().iter().map(|d| d.id()).collect();
        for a in <$family>::ALL {
            let d = a.declaration();
            assert_eq!(d.problem, $problem);
            assert!(
                registered.contains(&d.id()),
                "{} is not in declarations()",
                d.id()
            );
            assert_eq!(a.name(), d.name);
            assert_eq!(a.name().parse::<$family>().unwrap(), a);
            assert_eq!(a.to_string(), a.name());
        }
        let err = "no-such-algorithm"
            .parse::<$family>()
            .unwrap_err()
            .to_string();
        for a in <$family>::ALL {
            assert!(err.contains(a.name()), "{err}");
        }
    }};
}

#[test]
fn every_family_enum_is_its_declarations() {
    check_family!(compgeo::sort::Algorithm, "sort");
    check_family!(compgeo::graph::SearchAlgorithm, "search");
    check_family!(compgeo::graph::ColouringAlgorithm, "colour");
    check_family!(compgeo::graph::MstAlgorithm, "mst");
    check_family!(compgeo::hull::Algorithm, "hull");
    check_family!(compgeo::calipers::DiameterAlgorithm, "diameter");
    check_family!(compgeo::delaunay::Algorithm, "delaunay");
    check_family!(compgeo::proximity::ClosestPairAlgorithm, "closest-pair");
    check_family!(compgeo::spline::BezierEvaluation, "bezier");
}

/// The declarations of one family, as the command line lists them.
#[cfg(feature = "cli")]
fn family(
    declarations: impl IntoIterator<Item = &'static Declaration>,
) -> Vec<&'static Declaration> {
    declarations.into_iter().collect()
}

#[cfg(feature = "cli")]
#[test]
fn the_command_line_help_lists_every_declared_algorithm() {
    use crate::common::run;
    let d = |a: &'static Declaration| a;
    for (command, members) in [
        (
            "bezier eval",
            family(compgeo::spline::BezierEvaluation::ALL.map(|a| d(a.declaration()))),
        ),
        (
            "sort",
            family(compgeo::sort::Algorithm::ALL.map(|a| d(a.declaration()))),
        ),
        (
            "colour",
            family(compgeo::graph::ColouringAlgorithm::ALL.map(|a| d(a.declaration()))),
        ),
        (
            "mst",
            family(compgeo::graph::MstAlgorithm::ALL.map(|a| d(a.declaration()))),
        ),
        (
            "hull",
            family(compgeo::hull::Algorithm::ALL.map(|a| d(a.declaration()))),
        ),
        (
            "diameter",
            family(compgeo::calipers::DiameterAlgorithm::ALL.map(|a| d(a.declaration()))),
        ),
        (
            "delaunay",
            family(compgeo::delaunay::Algorithm::ALL.map(|a| d(a.declaration()))),
        ),
        (
            "closest-pair",
            family(compgeo::proximity::ClosestPairAlgorithm::ALL.map(|a| d(a.declaration()))),
        ),
    ] {
        let mut args: Vec<&str> = command.split(' ').collect();
        args.push("--help");
        let (code, help, _) = run(&args, None);
        assert_eq!(code, 0, "{command} --help");
        let help = help.split_whitespace().collect::<Vec<_>>().join(" ");
        for d in members {
            let line = format!("{}: {}, {}", d.name, d.summary, d.time);
            assert!(
                help.contains(&line),
                "`{command} --help` lacks {line:?}:\n{help}"
            );
        }
    }
}
