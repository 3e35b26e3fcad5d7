//! `lessons` and `render --lesson` end to end: the built-in decks listed, and every built-in
//! deck's handout in every language, one page per step whose text can be read back (with
//! pdf-extract, as pdftotext would), and its steps as SVG pictures.

use crate::cli;

use std::process::Command;

use cli::render;
use refraction_deck::{Deck, builtin};
use refraction_i18n::{Locale, set_locale};

fn lessons(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .arg("lessons")
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn lessons_lists_each_built_in_deck_with_its_title_and_steps() {
    let out = lessons(&[]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    let rows: Vec<Vec<&str>> = text.lines().map(|l| l.split('\t').collect()).collect();
    assert_eq!(rows.len(), builtin::names().len());
    assert_eq!(
        rows[0],
        ["snell", "Snell's law in ten minutes", "5"],
        "{text}"
    );
    for row in &rows {
        assert_eq!(row.len(), 3, "{row:?}");
        assert!(row[2].parse::<usize>().unwrap() >= 4, "{row:?}");
    }
    let german = String::from_utf8(lessons(&["--lang", "de"]).stdout).unwrap();
    assert!(german.starts_with("snell\t"), "{german}");
    assert_ne!(german, text, "the titles in German");
}

#[test]
fn every_built_in_decks_handout_has_a_page_per_step_with_its_words_in_every_language() {
    let folder = cli::folder("lessons-cli", "handouts");
    for locale in Locale::ALL {
        set_locale(locale);
        for name in builtin::names() {
            let deck = Deck::load(name).unwrap();
            let path = folder.join(format!("{name}-{}.pdf", locale.code()));
            let out = render(&[
                "--lesson",
                name,
                "--out",
                path.to_str().unwrap(),
                "--lang",
                locale.code(),
            ]);
            assert!(out.status.success(), "{locale} {name}: {out:?}");
            let bytes = std::fs::read(&path).unwrap();
            let pages = pdf_extract::extract_text_from_mem_by_pages(&bytes).unwrap();
            assert_eq!(pages.len(), deck.steps.len(), "{locale} {name}");
            // pdf-extract puts a space between glyphs that the PDF places one by one (as
            // svg2pdf does, kerning off): the words are compared without their spaces.
            let bare = |text: &str| text.split_whitespace().collect::<String>();
            for (page, step) in pages.iter().zip(&deck.steps) {
                let page = bare(page);
                for words in [Some(&step.title), step.question.as_ref(), Some(&step.notes)]
                    .into_iter()
                    .flatten()
                {
                    assert!(
                        page.contains(&bare(words)),
                        "{locale} {name}: {words} in {page}"
                    );
                }
            }
        }
    }
    set_locale(Locale::En);
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn a_folder_gets_one_svg_per_step_and_a_bad_out_or_deck_is_refused() {
    let folder = cli::folder("lessons-cli", "svgs");
    let out_dir = format!("{}/slides/", folder.display());
    let out = render(&["--lesson", "sign-conventions", "--out", &out_dir]);
    assert!(out.status.success(), "{out:?}");
    let mut names: Vec<String> = std::fs::read_dir(folder.join("slides"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "step-01.svg",
            "step-02.svg",
            "step-03.svg",
            "step-04.svg",
            "step-05.svg"
        ]
    );
    let svg = std::fs::read_to_string(folder.join("slides/step-02.svg")).unwrap();
    assert!(
        svg.contains("<title>") && !svg.contains("<text"),
        "labels outlined"
    );
    let png = folder.join("x.png");
    let refused = render(&["--lesson", "snell", "--out", png.to_str().unwrap()]);
    assert_eq!(refused.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&refused.stderr).contains("ending in .pdf"));
    let unknown = render(&["--lesson", "nope", "--out", &out_dir]);
    assert_eq!(unknown.status.code(), Some(2));
    let both = render(&["--lesson", "snell", "--state", "x.json", "--out", &out_dir]);
    assert_eq!(both.status.code(), Some(2), "--lesson or --state");
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn the_student_sheet_asks_the_questions_without_answers_or_notes() {
    let folder = cli::folder("lessons-cli", "students");
    let path = folder.join("snell-students.pdf");
    let out = render(&[
        "--lesson",
        "snell",
        "--students",
        "--out",
        path.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{out:?}");
    let deck = Deck::load("snell").unwrap();
    let pages =
        pdf_extract::extract_text_from_mem_by_pages(&std::fs::read(&path).unwrap()).unwrap();
    assert_eq!(pages.len(), deck.steps.len());
    let bare = |text: &str| text.split_whitespace().collect::<String>();
    for (page, step) in pages.iter().zip(&deck.steps) {
        let page = bare(page);
        assert!(page.contains(&bare(&step.title)), "{page}");
        if let Some(question) = &step.question {
            assert!(page.contains(&bare(question)), "{page}");
            // No T is drawn (a scene's step draws its rays up to the first surface), and the
            // window's furniture stays off paper: the banner names the convention, not how
            // to reveal the answer, and there is no index scale with its μ markers.
            let one = step.view == refraction_deck::StepView::One;
            assert!(!one || page.contains(&bare("Section 2")), "{page}");
            assert!(!page.contains(&bare("The answer is hidden")), "{page}");
            assert!(!page.contains("indexμ"), "{page}");
        }
        // Nor on a step that explains: it shows the same ray as step 1, and on paper its θt
        // would answer step 1's question a page back.
        assert!(!page.contains("θt="), "{page}");
        assert!(!page.contains(&bare(&step.notes)), "no notes: {page}");
    }
    let teacher = folder.join("snell.pdf");
    let out = render(&["--lesson", "snell", "--out", teacher.to_str().unwrap()]);
    assert!(out.status.success(), "{out:?}");
    let text =
        bare(&pdf_extract::extract_text_from_mem(&std::fs::read(&teacher).unwrap()).unwrap());
    assert!(
        text.contains(&bare(&deck.steps[0].notes)),
        "the teacher's has the notes"
    );
    std::fs::remove_dir_all(&folder).unwrap();
}

/// The names in `folder`, sorted.
fn names_in(folder: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(folder)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn a_folder_of_steps_is_written_whole_or_not_at_all_and_keeps_no_stale_step() {
    // Issue 31: steps 1-2 were replaced before step 3 failed, and a shorter deck left a longer
    // one's step-06.svg behind.
    let folder = cli::folder("lessons-cli", "all-or-nothing");
    let out_dir = format!("{}/", folder.display());
    let six = render(&["--lesson", "total-internal-reflection", "--out", &out_dir]);
    assert!(six.status.success(), "{six:?}");
    std::fs::write(folder.join("step-09.svg"), "my own picture").unwrap();
    let five = render(&["--lesson", "snell", "--out", &out_dir]);
    assert!(five.status.success(), "{five:?}");
    let mut expected: Vec<String> = (1..=5).map(|i| format!("step-{i:02}.svg")).collect();
    expected.push("step-09.svg".to_owned());
    assert_eq!(
        names_in(&folder),
        expected,
        "step-06 removed, a file not ours kept"
    );
    let before = std::fs::read(folder.join("step-01.svg")).unwrap();
    std::fs::remove_file(folder.join("step-03.svg")).unwrap();
    std::fs::create_dir(folder.join("step-03.svg")).unwrap();
    let failed = render(&["--lesson", "sign-conventions", "--out", &out_dir]);
    assert_eq!(failed.status.code(), Some(2), "{failed:?}");
    assert!(String::from_utf8_lossy(&failed.stderr).contains("step-03.svg: it is a directory"));
    assert_eq!(
        std::fs::read(folder.join("step-01.svg")).unwrap(),
        before,
        "nothing written"
    );
    assert!(
        !names_in(&folder)
            .iter()
            .any(|n| n.starts_with(".refraction-"))
    );
    for (width, height) in [("0", "600"), ("800", "999999")] {
        let pdf = folder.join("handout.pdf");
        let args = [
            "--lesson", "snell", "--width", width, "--height", height, "--out",
        ];
        let refused = render(&[&args[..], &[pdf.to_str().unwrap()]].concat());
        assert_eq!(
            refused.status.code(),
            Some(2),
            "{width}×{height}: {refused:?}"
        );
        assert!(!pdf.exists());
    }
    std::fs::remove_dir_all(&folder).unwrap();
}

#[test]
fn the_window_refuses_a_deck_it_cannot_read_before_it_opens() {
    let out = Command::new(env!("CARGO_BIN_EXE_refraction-explorer"))
        .args(["--lesson", "no-such-deck.toml"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let said = String::from_utf8_lossy(&out.stderr);
    assert!(
        said.starts_with("refraction-explorer: no-such-deck.toml: cannot read"),
        "{said}"
    );
}
