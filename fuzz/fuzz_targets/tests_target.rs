//! Where `check --tests` (and the window's *Save failing lines as tests*) may write: any bytes
//! already in the file, under each language's name, are either refused or found to be a test
//! file of ours, from the file's first bytes alone, and nothing is written.
#![no_main]

use refraction_check::tests_file::{TESTS_MARK, TestLanguage, replaces};
use refraction_check::{AnyLanguage, Dialect};

libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    let folder = std::env::temp_dir().join(format!("tests-target-{}", std::process::id()));
    std::fs::create_dir_all(&folder).ok();
    for language in [
        TestLanguage::Any(AnyLanguage::Cpp),
        TestLanguage::Any(AnyLanguage::Python),
    ] {
        let path = folder.join(format!("t.{}", language.extension()));
        std::fs::write(&path, data).expect("the fuzzer's folder is writable");
        let ours = data.is_empty()
            || data.starts_with(format!("{} {TESTS_MARK}", language.comment()).as_bytes());
        match replaces(&path, language) {
            Ok(replaced) => assert!(replaced && ours, "{data:?}"),
            Err(_) => assert!(!ours, "{data:?}"),
        }
        assert_eq!(
            std::fs::read(&path).expect("still there"),
            data,
            "nothing is written"
        );
        assert!(TestLanguage::for_path(Dialect::Physics, &path).is_some());
    }
});
