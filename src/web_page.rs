//! The HTML page that loads the web build, as `cargo xtask web` writes it: `index.html`
//! beside the module wasm-bindgen wrote (for a web server), or one file with the module and the
//! WebAssembly inlined (for a USB stick: it opens from `file://` with no network).
//!
//! The page says, in the browser's language, that the explorer is loading and, if the browser
//! cannot run it, why; the window itself takes over once it runs. Its words come from the
//! explorer's own translations, so that they are in all six languages.

use refraction_i18n::{Locale, set_locale, t};

use crate::TITLE;

/// The id of the page's canvas, which the module starts the explorer on.
pub const CANVAS_ID: &str = "explorer";

/// The id of the line that says the explorer is loading; the module removes it once the
/// window runs.
pub const LOADING_ID: &str = "loading";

/// The id of the container of the page's own controls for screen readers and keyboards (before
/// the canvas in the tab order), which the module fills: out of sight until one of them has the
/// keyboard, then a bar over the foot of the page.
pub const CONTROLS_ID: &str = "explorer-controls";

/// The CSS of [`CONTROLS_ID`]: hidden as screen readers still read it (not `display: none`)
/// until a control inside has the focus, then a bar with 44-pixel controls and a focus ring
/// that shows.
const CONTROLS_CSS: &str = "#explorer-controls { position: fixed; left: 0; right: 0; bottom: 0; \
     z-index: 2; display: flex; flex-wrap: wrap; align-items: center; gap: 4px 16px; padding: \
     8px 12px; background: #ffffff; color: #1a1a1a; border-top: 2px solid #1a1a1a; font: 16px \
     sans-serif; }\n#explorer-controls:not(:focus-within) { width: 1px; height: 1px; padding: \
     0; overflow: hidden; clip-path: inset(50%); white-space: nowrap; }\n#explorer-controls p \
     { margin: 0; flex-basis: 100%; }\n#explorer-controls div { display: flex; align-items: \
     center; gap: 8px; }\n#explorer-controls [hidden] { display: none; }\n#explorer-controls \
     input, #explorer-controls button { min-height: 44px; min-width: 44px; font: inherit; }\n\
     #explorer-controls input[type=number] { width: 7em; }\n\
     #explorer-controls :focus { outline: 3px solid #0b57d0; outline-offset: 2px; }\n#diagram-words { position: absolute; width: 1px; height: 1px; overflow: hidden; \
     clip-path: inset(50%); white-space: nowrap; }\n";

/// How the page gets the module.
#[derive(Clone, Copy, Debug)]
pub enum Script<'a> {
    /// From the file wasm-bindgen wrote beside the page (`NAME.js`, which loads `NAME_bg.wasm`).
    Beside {
        /// The script's file name.
        js: &'a str,
    },
    /// Inlined: the script wasm-bindgen wrote (exporting nothing) and the
    /// WebAssembly as base64, handed to the script's init function as bytes.
    Inlined {
        /// The script's text.
        js: &'a str,
        /// The module, base64.
        wasm_base64: &'a str,
    },
}

/// JavaScript's text for `text`, quoted (JSON strings are JavaScript strings).
fn quoted(text: &str) -> String {
    serde_json::Value::String(text.to_owned()).to_string()
}

/// The page's words in every language, as a JavaScript object keyed by language code.
fn words() -> String {
    let before = refraction_i18n::locale();
    let entries: Vec<String> = Locale::ALL
        .iter()
        .map(|&locale| {
            set_locale(locale);
            format!(
                "{}: {{ loading: {}, failed: {} }}",
                quoted(locale.code().split('-').next().unwrap_or_default()),
                quoted(&t!("web-page-loading")),
                quoted(&t!("web-page-failed", reason = "{reason}")),
            )
        })
        .collect();
    set_locale(before);
    format!("{{ {} }}", entries.join(",\n  "))
}

/// The module script: picks the browser's language for the page's words, then loads the
/// explorer (which removes the loading line once it runs) or says why it could not.
fn bootstrap(script: &Script<'_>) -> String {
    let (import, init) = match script {
        Script::Beside { js } => (
            format!("import init from {};", quoted(&format!("./{js}"))),
            "await init();".to_owned(),
        ),
        Script::Inlined { js, wasm_base64 } => {
            // A module inlined in the page exports nothing: its export list goes, and its
            // exported functions stay as plain functions.
            let module: String = js
                .lines()
                .filter(|line| !line.starts_with("export {"))
                .map(|line| line.strip_prefix("export ").unwrap_or(line))
                .collect::<Vec<_>>()
                .join("\n");
            let load = format!(
                "const text = atob({});\n  const bytes = new Uint8Array(text.length);\n  \
                 for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);\n  \
                 await __wbg_init({{ module_or_path: bytes }});",
                quoted(wasm_base64)
            );
            (module, load)
        }
    };
    format!(
        "{import}\nconst words = {words};\nconst languages = navigator.languages || \
         [navigator.language || 'en'];\nconst language = languages.map((l) => \
         l.split('-')[0]).find((l) => l in words) || 'en';\nconst said = words[language];\n\
         document.documentElement.lang = language;\nconst line = \
         document.getElementById({loading});\nline.textContent = said.loading;\ntry {{\n  \
         {init}\n}} catch (e) {{\n  line.textContent = said.failed.replace('{{reason}}', \
         String(e));\n  line.className = 'failed';\n  throw e;\n}}\n",
        words = words(),
        loading = quoted(LOADING_ID),
    )
}

/// The page, loading the module as `script` says.
#[must_use]
pub fn html(script: &Script<'_>) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" \
         content=\"width=device-width, initial-scale=1\">\n<title>{TITLE}</title>\n<link rel=\"icon\" href=\"data:,\">\n<style>\n\
         html, body {{ margin: 0; padding: 0; width: 100%; height: 100%; overflow: hidden; \
         background: #f8f8f8; }}\ncanvas {{ position: absolute; top: 0; left: 0; width: 100%; \
         height: 100%; display: block; }}\n#{LOADING_ID} {{ position: absolute; top: 45%; \
         width: 100%; text-align: center; font: 20px sans-serif; color: #333; }}\n\
         #{LOADING_ID}.failed {{ color: #a00000; }}\n{CONTROLS_CSS}</style>\n</head>\n<body>\n\
         <section id=\"{CONTROLS_ID}\"></section>\n<canvas id=\"{CANVAS_ID}\"></canvas>\n<p id=\"{LOADING_ID}\">…</p>\n<script \
         type=\"module\">\n{}</script>\n</body>\n</html>\n",
        bootstrap(script).replace("</script", "<\\/script")
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_page_loads_the_module_beside_it_or_inlined() {
        let beside = html(&Script::Beside {
            js: "refraction_web.js",
        });
        assert!(beside.contains("import init from \"./refraction_web.js\";"));
        assert!(beside.contains("<canvas id=\"explorer\">"));
        assert!(beside.contains("<html lang=\"en\">"));
        let controls = beside.find("<section id=\"explorer-controls\">");
        assert!(
            controls < beside.find("<canvas"),
            "the controls come first when tabbing"
        );
        assert!(
            beside.contains("\"de\": { loading:"),
            "every language's words"
        );
        let inlined = html(&Script::Inlined {
            js: "export function start() {}\nasync function __wbg_init() {}\n\
                 export { initSync, __wbg_init as default };",
            wasm_base64: "AGFzbQ==",
        });
        assert!(
            !inlined.contains("export "),
            "the module's exports are dropped"
        );
        assert!(inlined.contains("atob(\"AGFzbQ==\")"));
        assert!(inlined.contains("module_or_path: bytes"));
    }
}
