//! The documentation's citations of the handouts and the errata cannot dangle.
//!
//! Doc comments cite the lecture handouts ("seed 000", "seed 003") and their slips
//! ("ERRATA #n"); the pages `src/handouts.md` and `src/errata.md` (rendered as
//! `lobe::handouts` and `lobe::errata`) define them. rustdoc checks that a link's item exists
//! but not its `#fragment`, so this test does:
//!
//! * every `ERRATA #n` in `src/**/*.rs`, doc comment or not, has its heading
//!   `### Erratum n — …` on the errata page, and the page numbers its entries 1, 2, … without
//!   gaps or repeats;
//! * in a doc comment (`///`, `//!`, outside code blocks) every `ERRATA #n` is the link
//!   `[ERRATA #n](crate::errata#erratum-n--…)` to that heading;
//! * every `crate::errata#…` and `crate::handouts#…` link in `src/`, every inline `](#…)`
//!   link within the two pages (outside fenced code) and every `src/errata.md#…` or
//!   `src/handouts.md#…` link in the README names a heading that exists (with the id rustdoc,
//!   and GitHub, derive from it);
//! * every entry of the errata page says what pins it, and the test files and functions it
//!   names exist, each function in the file named before it.
//! * every inline link between the README and the pages under `docs/`, and within each of
//!   them, to a `#fragment` names a heading that exists.

use std::collections::BTreeSet;
use std::fs;
use std::path::{Path, PathBuf};

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn read(path: &Path) -> String {
    fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Every `.rs` file under `dir`, recursively, sorted.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display())) {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|x| x == "rs") {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

/// The id rustdoc gives a heading (`IdMap` in rustdoc's markdown renderer): ASCII letters
/// lowercased, other alphanumerics, `-` and `_` kept, ASCII whitespace turned into `-`,
/// everything else dropped. For the plain ASCII headings of the two pages GitHub derives the
/// same id.
fn slug(heading: &str) -> String {
    heading
        .chars()
        .filter_map(|c| {
            if c.is_alphanumeric() || c == '-' || c == '_' {
                Some(c.to_ascii_lowercase())
            } else if c.is_ascii_whitespace() {
                Some('-')
            } else {
                None
            }
        })
        .collect()
}

/// A markdown page's headings, in order: `(level, text, id)`. Fenced code is skipped.
fn headings(page: &str) -> Vec<(usize, String, String)> {
    let mut out = Vec::new();
    for line in outside_fences(page).lines() {
        let level = line.chars().take_while(|&c| c == '#').count();
        if level == 0 || !line[level..].starts_with(' ') {
            continue;
        }
        let text = line[level..].trim().to_string();
        let id = slug(&text);
        out.push((level, text, id));
    }
    out
}

/// A page's heading ids, which must be unique (rustdoc would suffix a repeat with `-1`).
fn ids(name: &str, page: &str) -> BTreeSet<String> {
    let mut set = BTreeSet::new();
    for (_, text, id) in headings(page) {
        assert!(
            set.insert(id.clone()),
            "{name}: two headings have the id {id:?} ({text:?})"
        );
    }
    set
}

/// Every `n` of `ERRATA #n` in `text`, with its byte offset.
fn citations(text: &str) -> Vec<(usize, u32)> {
    const KEY: &str = "ERRATA #";
    text.match_indices(KEY)
        .filter_map(|(at, _)| {
            let digits: String = text[at + KEY.len()..]
                .chars()
                .take_while(char::is_ascii_digit)
                .collect();
            digits.parse().ok().map(|n| (at, n))
        })
        .collect()
}

/// The fragments of the links in `text` whose target starts with `prefix` and a `#`:
/// `prefix#fragment`, up to the closing parenthesis.
fn fragments<'a>(text: &'a str, prefix: &str) -> Vec<&'a str> {
    let key = format!("{prefix}#");
    text.match_indices(&key)
        .map(|(at, _)| {
            let rest = &text[at + key.len()..];
            let end = rest
                .find(|c: char| c == ')' || c.is_whitespace())
                .unwrap_or(rest.len());
            &rest[..end]
        })
        .collect()
}

struct Pages {
    errata: String,
    handouts: String,
    errata_ids: BTreeSet<String>,
    handouts_ids: BTreeSet<String>,
}

impl Pages {
    fn load() -> Self {
        let errata = read(&root().join("src/errata.md"));
        let handouts = read(&root().join("src/handouts.md"));
        let errata_ids = ids("src/errata.md", &errata);
        let handouts_ids = ids("src/handouts.md", &handouts);
        Self {
            errata,
            handouts,
            errata_ids,
            handouts_ids,
        }
    }

    /// The id of erratum `n`'s heading, `erratum-n--…`.
    fn erratum(&self, n: u32) -> Option<&String> {
        let prefix = format!("erratum-{n}--");
        self.errata_ids.iter().find(|id| id.starts_with(&prefix))
    }

    /// Checks the links of `text` (from `origin`) into the two pages: each target is a link
    /// prefix (`crate::errata`, `src/errata.md`, or `](` for a page's links to its own
    /// headings) with the ids its fragments must be among. Returns how many links it checked
    /// for each target.
    fn check_links(
        &self,
        origin: &str,
        text: &str,
        targets: &[(&str, &BTreeSet<String>)],
        bad: &mut Vec<String>,
    ) -> Vec<usize> {
        let mut counts = Vec::new();
        for (prefix, ids) in targets {
            let found = fragments(text, prefix);
            for fragment in &found {
                if !ids.contains(*fragment) {
                    bad.push(format!(
                        "{origin}: the link {prefix}#{fragment} names no heading"
                    ));
                }
            }
            counts.push(found.len());
        }
        counts
    }
}

#[test]
fn errata_page_numbers_its_entries_without_gaps() {
    let pages = Pages::load();
    let numbers: Vec<u32> = headings(&pages.errata)
        .iter()
        .filter_map(|(_, text, _)| {
            let rest = text.strip_prefix("Erratum ")?;
            let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
            digits.parse().ok()
        })
        .collect();
    let want: Vec<u32> = (1..=numbers.len() as u32).collect();
    assert_eq!(numbers, want, "the errata page's entries, in order");
    // The twelve slips of the handouts are all there.
    assert!(numbers.len() >= 12, "{} entries", numbers.len());
    for n in numbers {
        assert!(
            pages.erratum(n).is_some(),
            "entry {n}: write its heading as `### Erratum {n} — title`, whose id is \
             `erratum-{n}--title`"
        );
    }
}

#[test]
fn every_errata_citation_in_src_has_an_anchor_and_doc_comments_link_it() {
    let pages = Pages::load();
    let mut bad = Vec::new();
    let mut cited = BTreeSet::new();
    let mut linked = 0;
    for path in rust_files(&root().join("src")) {
        let name = path.strip_prefix(root()).unwrap().display().to_string();
        let mut in_code = false;
        for (i, line) in read(&path).lines().enumerate() {
            let origin = format!("{name}:{}", i + 1);
            let trimmed = line.trim_start();
            let doc = trimmed
                .strip_prefix("///")
                .or_else(|| trimmed.strip_prefix("//!"));
            match doc {
                Some(text) if text.trim_start().starts_with("```") => in_code = !in_code,
                Some(_) => {}
                None => in_code = false,
            }
            for (at, n) in citations(line) {
                cited.insert(n);
                let Some(id) = pages.erratum(n) else {
                    bad.push(format!(
                        "{origin}: ERRATA #{n} has no `### Erratum {n} — …` on src/errata.md"
                    ));
                    continue;
                };
                if doc.is_none() || in_code {
                    continue;
                }
                let link = format!("[ERRATA #{n}](crate::errata#{id})");
                if line[..at].ends_with('[') && line[at - 1..].starts_with(&link) {
                    linked += 1;
                } else {
                    bad.push(format!("{origin}: link the citation: write {link}"));
                }
            }
            pages.check_links(
                &origin,
                line,
                &[
                    ("crate::errata", &pages.errata_ids),
                    ("crate::handouts", &pages.handouts_ids),
                ],
                &mut bad,
            );
        }
    }
    eprintln!("ERRATA numbers cited in src/: {cited:?}; doc-comment citations linked: {linked}");
    assert!(bad.is_empty(), "{bad:#?}");
    assert!(linked > 0, "no linked citation found: is the scan broken?");
}

/// The errata and handouts pages' inline links to their own headings (`](#…`, outside fenced
/// code) and their `crate::errata#…`/`crate::handouts#…` links, and the README's links into
/// the two pages, name headings that exist. Each kind of link the pages have today must be
/// found (own headings, a page into the errata, the README into each page), so that the scan
/// cannot pass by finding nothing; the pages have no `crate::handouts#…` link.
#[test]
fn links_within_and_into_the_pages_name_existing_headings() {
    let pages = Pages::load();
    let mut bad = Vec::new();
    let (mut own, mut into_errata, mut into_handouts) = (0, 0, 0);
    for (name, page, own_ids) in [
        ("src/errata.md", &pages.errata, &pages.errata_ids),
        ("src/handouts.md", &pages.handouts, &pages.handouts_ids),
    ] {
        let [to_own, to_errata, to_handouts] = pages.check_links(
            name,
            &outside_fences(page),
            &[
                ("](", own_ids),
                ("crate::errata", &pages.errata_ids),
                ("crate::handouts", &pages.handouts_ids),
            ],
            &mut bad,
        )[..] else {
            unreachable!("one count per target")
        };
        own += to_own;
        into_errata += to_errata;
        into_handouts += to_handouts;
    }
    let readme = outside_fences(&read(&root().join("README.md")));
    let [readme_errata, readme_handouts] = pages.check_links(
        "README.md",
        &readme,
        &[
            ("src/errata.md", &pages.errata_ids),
            ("src/handouts.md", &pages.handouts_ids),
        ],
        &mut bad,
    )[..] else {
        unreachable!("one count per target")
    };
    eprintln!(
        "links checked: {own} within a page, {into_errata} from a page into the errata, \
         {into_handouts} into the handouts, {readme_errata} from the README into the errata, \
         {readme_handouts} into the handouts"
    );
    assert!(bad.is_empty(), "{bad:#?}");
    assert!(
        own > 0 && into_errata > 0 && readme_errata > 0 && readme_handouts > 0,
        "a kind of link was not found: is the scan broken?"
    );
}

/// The README and the pages under `docs/` link to each other's headings and to their own; every
/// such link names a heading that exists, so that a section moved from one to another leaves no
/// inline link (`[text](target#fragment)`, outside fenced code) behind that points at nothing.
/// A page spells a link to itself `](#…`, the README a link to a page `](docs/page.md#…`, and a
/// page under `docs/` a link to another `](page.md#…` and to the README `](../README.md#…`. Each
/// page's headings must have distinct ids, as the errata and handouts pages' must. Links from
/// elsewhere (the CHANGELOG, doc comments) and prose references ("the README's …") are not
/// checked.
#[test]
fn links_between_the_readme_and_the_docs_pages_name_existing_headings() {
    let mut pages = vec![("README.md".to_string(), read(&root().join("README.md")))];
    let mut docs: Vec<PathBuf> = fs::read_dir(root().join("docs"))
        .expect("docs/")
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|x| x == "md"))
        .collect();
    docs.sort();
    for path in docs {
        let name = format!("docs/{}", path.file_name().unwrap().to_string_lossy());
        pages.push((name, read(&path)));
    }
    let page_ids: Vec<BTreeSet<String>> = pages.iter().map(|(n, text)| ids(n, text)).collect();
    let mut bad = Vec::new();
    // Links checked: to the page's own headings, from the README to docs/, from docs/ onwards.
    let (mut own, mut from_readme, mut from_docs) = (0, 0, 0);
    for (origin, text) in &pages {
        let text = outside_fences(text);
        for ((target, _), target_ids) in pages.iter().zip(&page_ids) {
            let (prefix, count) = if target == origin {
                ("](".to_string(), &mut own)
            } else if origin.starts_with("docs/") {
                let prefix = match target.strip_prefix("docs/") {
                    Some(page) => format!("]({page}"),
                    None => format!("](../{target}"),
                };
                (prefix, &mut from_docs)
            } else {
                (format!("]({target}"), &mut from_readme)
            };
            for fragment in fragments(&text, &prefix) {
                *count += 1;
                if !target_ids.contains(fragment) {
                    bad.push(format!(
                        "{origin}: the link {}#{fragment}) names no heading of {target}",
                        &prefix[1..]
                    ));
                }
            }
        }
    }
    eprintln!(
        "links checked: {own} within a page, {from_readme} from the README to docs/, \
         {from_docs} from docs/"
    );
    assert!(bad.is_empty(), "{bad:#?}");
    assert!(
        own > 0 && from_readme > 0 && from_docs > 0,
        "a kind of link was not found: is the scan broken?"
    );
}

/// `text` without its fenced code blocks (their lines are dropped, fences included).
fn outside_fences(text: &str) -> String {
    let mut fenced = false;
    let mut out = String::new();
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if !fenced {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// Each entry of the errata page (a `###` heading) has a "Pinned by" part, and every file and
/// function it names in backticks exists, the function in the file named before it
/// (`` `tests/fresnel.rs`, `slipped_schlick_is_caught…` ``, `` `src/fresnel.rs`,
/// `tests::schlick_raises…` ``), so that a renamed or moved test does not leave the page
/// pointing at nothing.
#[test]
fn errata_entries_name_tests_that_exist() {
    let pages = Pages::load();
    let defines = |file: &str, f: &str| read(&root().join(file)).contains(&format!("fn {f}("));
    let mut bad = Vec::new();
    let mut named = 0;
    // The page split at its `###` headings; the first piece is the introduction.
    for entry in pages.errata.split("\n### ").skip(1) {
        let title = entry.lines().next().unwrap_or_default();
        let entry = entry.split("\n## ").next().unwrap_or_default();
        let Some((_, pinned)) = entry.split_once("**Pinned by**") else {
            bad.push(format!("{title}: no **Pinned by**"));
            continue;
        };
        let mut file: Option<&str> = None;
        for token in pinned.split('`').skip(1).step_by(2) {
            if token.ends_with(".rs") {
                named += 1;
                if root().join(token).is_file() {
                    file = Some(token);
                } else {
                    bad.push(format!("{title}: no file {token}"));
                    file = None;
                }
            } else if token.contains('_')
                && token
                    .chars()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_' || c == ':')
            {
                named += 1;
                let function = token.rsplit("::").next().unwrap();
                match file {
                    Some(file) if !defines(file, function) => {
                        bad.push(format!("{title}: no fn {function} in {file}"));
                    }
                    None => bad.push(format!("{title}: {function} named before any file")),
                    _ => {}
                }
            }
        }
    }
    eprintln!("files and functions named by the errata page: {named}");
    assert!(bad.is_empty(), "{bad:#?}");
    assert!(
        named >= 30,
        "only {named} names found: is the parse broken?"
    );
}
