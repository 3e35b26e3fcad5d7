//! The HTML page that loads the web build, as `cargo xtask web` writes it: `index.html`
//! beside the module wasm-bindgen wrote (for a web server), or one file with the module and the
//! WebAssembly inlined (for a USB stick: it opens from `file://` with no network).
//!
//! The page says, in the browser's language, that the explorer is loading and, if the browser
//! cannot run it, why; the window itself takes over once it runs. Its words come from the
//! explorer's own translations, so that they are in all six languages.
//!
//! Beside the module, the folder's page links a web app manifest ([`manifest`]) and registers a
//! service worker ([`service_worker`]) that keeps the build for use with no network, so that a
//! Chromebook or a phone can install the page as an app. Both pages show a panic over the page
//! (what the program said, a link that reloads, and the link of the last state, which the
//! window keeps in [`LINK_ATTRIBUTE`]) instead of a frozen picture, and offer to open the
//! explorer in a tab of its own when it runs inside another page.

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

// The installable, offline page and the panic overlay (issue 44): the ids and file names the
// module, xtask and the tests share.

/// The id of the box shown over the page when the program panics.
pub const CRASH_ID: &str = "crashed";

/// The id of the link that opens the explorer in a tab of its own, shown when the page is
/// inside another page (a learning platform's frame).
pub const NEW_TAB_ID: &str = "new-tab";

/// The attribute of the page's root element that holds the fragment of the last state's link
/// (`state=…` or `lesson=…&step=…`, without `#`): the window keeps it, and the panic overlay
/// and the new tab's link read it.
pub const LINK_ATTRIBUTE: &str = "data-link";

/// The fragment that panics the window on purpose, in a build with debug assertions only (the
/// browser test of the panic overlay); no link the explorer makes has it.
pub const DEBUG_PANIC_FRAGMENT: &str = "debug-panic-on-purpose";

/// The web app manifest's file name, beside `index.html`.
pub const MANIFEST: &str = "manifest.webmanifest";

/// The service worker's file name, beside `index.html` (its folder is what it controls).
pub const SERVICE_WORKER: &str = "service-worker.js";

/// The app's icons, beside `index.html`: each file name and its size in pixels.
pub const ICONS: [(&str, u32); 2] = [("icon-192.png", 192), ("icon-512.png", 512)];

/// The browser's colour around the installed app (the page's background).
const BACKGROUND: &str = "#f8f8f8";

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
                "{}: {{ loading: {}, failed: {}, crashed: {}, reload: {}, reopen: {}, \
                 newTab: {}, newTabHover: {} }}",
                quoted(locale.code().split('-').next().unwrap_or_default()),
                quoted(&t!("web-page-loading")),
                quoted(&t!("web-page-failed", reason = "{reason}")),
                quoted(&t!("web-crash-title")),
                quoted(&t!("web-crash-reload")),
                quoted(&t!("web-crash-reopen")),
                quoted(&t!("web-open-in-tab")),
                quoted(&t!("web-open-in-tab-hover")),
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
    let register = match script {
        Script::Beside { .. } => INSTALLABLE.replace("SERVICE_WORKER", &quoted(SERVICE_WORKER)),
        Script::Inlined { .. } => String::new(),
    };
    format!(
        "{import}\nconst words = {words};\nconst languages = navigator.languages || \
         [navigator.language || 'en'];\nconst language = languages.map((l) => \
         l.split('-')[0]).find((l) => l in words) || 'en';\nconst said = words[language];\n\
         document.documentElement.lang = language;\n{{\n{overlay}}}\nconst line = \
         document.getElementById({loading});\nline.textContent = said.loading;\ntry {{\n  \
         {init}\n}} catch (e) {{\n  line.textContent = said.failed.replace('{{reason}}', \
         String(e));\n  line.className = 'failed';\n  throw e;\n}}\n{register}",
        words = words(),
        loading = quoted(LOADING_ID),
        overlay = OVERLAY_SCRIPT
            .replace("CRASH_ID", &quoted(CRASH_ID))
            .replace("NEW_TAB_ID", &quoted(NEW_TAB_ID))
            .replace("LINK_ATTRIBUTE", &quoted(LINK_ATTRIBUTE)),
    )
}

// The panic overlay and the new tab's link (issue 44): the script, the elements and their
// style. The script's names in capitals are replaced by the quoted constants.

/// What the page does when the program panics (the module calls `refractionCrashed` with
/// what it said) and, inside another page, the link that opens a tab of its own. The links go
/// to the last state's link (the root's `LINK_ATTRIBUTE`), loaded afresh: the program that
/// panicked can no longer follow a changed fragment.
const OVERLAY_SCRIPT: &str = "const root = document.documentElement;
const lastLink = () => {
  const fragment = root.getAttribute(LINK_ATTRIBUTE);
  const here = location.href.split('#')[0];
  return fragment ? `${here}#${fragment}` : location.href;
};
const loadAfresh = (address) => (event) => {
  event.preventDefault();
  location.replace(address);
  location.reload();
};
window.refractionCrashed = (message) => {
  const box = document.getElementById(CRASH_ID);
  if (!box.hidden) return;
  box.querySelector('h1').textContent = said.crashed;
  box.querySelector('pre').textContent = message;
  const reload = box.querySelector('.reload');
  reload.textContent = said.reload;
  reload.href = location.href;
  reload.onclick = loadAfresh(location.href);
  const address = lastLink();
  const reopen = box.querySelector('.reopen');
  reopen.textContent = said.reopen;
  reopen.href = address;
  reopen.onclick = loadAfresh(address);
  box.querySelector('code').textContent = address;
  box.hidden = false;
  box.focus();
};
if (window.self !== window.top) {
  const tab = document.getElementById(NEW_TAB_ID);
  tab.textContent = said.newTab;
  tab.title = said.newTabHover;
  tab.onclick = () => { tab.href = lastLink(); };
  tab.hidden = false;
}
";

/// The served folder's page registers its service worker once the explorer runs (so that its
/// copy of the build does not slow the first load); a page over plain http has none.
const INSTALLABLE: &str = "if ('serviceWorker' in navigator) {
  navigator.serviceWorker.register(SERVICE_WORKER).catch((e) => console.warn(e));
}
";

/// The panic overlay's box and the new tab's link, hidden until the script shows them.
fn overlay_elements() -> String {
    format!(
        "<div id=\"{CRASH_ID}\" role=\"alert\" tabindex=\"-1\" hidden><h1></h1><pre></pre>\
         <p><a class=\"reload\" href=\"\"></a></p><p><a class=\"reopen\" href=\"\"></a><br>\
         <code></code></p></div>\n<a id=\"{NEW_TAB_ID}\" href=\"\" target=\"_blank\" \
         rel=\"noopener\" hidden></a>\n"
    )
}

/// The overlay's style: large, dark on light (above 4.5:1), over everything.
fn overlay_style() -> String {
    format!(
        "#{CRASH_ID} {{ position: fixed; inset: 0; z-index: 10; overflow: auto; padding: 4vh 5vw; \
         background: rgba(248, 248, 248, 0.96); color: #1a1a1a; font: 20px sans-serif; }}\n\
         #{CRASH_ID} h1 {{ font-size: 28px; }}\n#{CRASH_ID} pre {{ white-space: pre-wrap; \
         font: 16px monospace; color: #6e0000; background: #fff; border: 1px solid #a00000; \
         padding: 12px; }}\n#{CRASH_ID} code {{ font: 16px monospace; word-break: break-all; }}\n\
         #{CRASH_ID} a, #{NEW_TAB_ID} {{ color: #0645ad; }}\n#{NEW_TAB_ID} {{ position: fixed; \
         right: 8px; bottom: 8px; z-index: 5; font: 16px sans-serif; background: #fff; \
         border: 1px solid #767676; border-radius: 6px; padding: 6px 10px; }}\n\
         [hidden] {{ display: none !important; }}\n"
    )
}

/// The head's links of the served folder's page: its manifest and its icon (the single file
/// has neither: a file cannot be installed, and it loads nothing beside it).
fn installable_head(script: &Script<'_>) -> String {
    match script {
        Script::Beside { .. } => format!(
            "<link rel=\"manifest\" href=\"{MANIFEST}\">\n<link rel=\"icon\" href=\"{}\">\n\
             <meta name=\"theme-color\" content=\"{BACKGROUND}\">\n",
            ICONS[0].0
        ),
        Script::Inlined { .. } => "<link rel=\"icon\" href=\"data:,\">\n".to_owned(),
    }
}

/// The web app manifest of the served folder: what a browser needs to install the page as an
/// app (its name, icons, the address it starts at and how it is shown).
#[must_use]
pub fn manifest() -> String {
    let icons: Vec<serde_json::Value> = ICONS
        .iter()
        .map(|(file, size)| {
            serde_json::json!({
                "src": file,
                "sizes": format!("{size}x{size}"),
                "type": "image/png",
                "purpose": "any",
            })
        })
        .collect();
    let manifest = serde_json::json!({
        "name": TITLE,
        "short_name": TITLE,
        "description": t!("web-manifest-description"),
        "lang": "en",
        "start_url": "./",
        "scope": "./",
        "display": "standalone",
        "background_color": BACKGROUND,
        "theme_color": BACKGROUND,
        "icons": icons,
    });
    format!("{manifest:#}\n")
}

/// The prefix of every cache the service worker makes; the build's name follows it.
pub const CACHE_PREFIX: &str = "refraction-explorer-";

/// The service worker of the served folder: it keeps `files` (beside it, the page's address
/// `./` included) in a cache named after `build`, answers from that cache first (so the page
/// opens with no network), and once a new build's worker takes over, removes every other
/// build's cache. A new build is fetched in the background on a visit after the folder is
/// updated and shown from the next one.
#[must_use]
pub fn service_worker(build: &str, files: &[&str]) -> String {
    let files: Vec<String> = core::iter::once("./")
        .chain(files.iter().copied())
        .map(quoted)
        .collect();
    SERVICE_WORKER_SCRIPT
        .replace("CACHE_NAME", &quoted(&format!("{CACHE_PREFIX}{build}")))
        .replace("CACHE_PREFIX", &quoted(CACHE_PREFIX))
        .replace("FILES", &format!("[{}]", files.join(", ")))
}

/// The service worker's script; the names in capitals are replaced by [`service_worker`].
const SERVICE_WORKER_SCRIPT: &str =
    "// The refraction explorer's service worker, written by cargo xtask web: it keeps this
// build's files so that the page opens with no network. Its cache is named after the build:
// a new build's worker fills a cache of its own, then removes the others.
const CACHE = CACHE_NAME;
self.addEventListener('install', (event) => {
  event.waitUntil(caches.open(CACHE)
    .then((cache) => cache.addAll(FILES))
    .then(() => self.skipWaiting()));
});
self.addEventListener('activate', (event) => {
  event.waitUntil(caches.keys()
    .then((names) => Promise.all(names
      .filter((name) => name.startsWith(CACHE_PREFIX) && name !== CACHE)
      .map((name) => caches.delete(name))))
    .then(() => self.clients.claim()));
});
self.addEventListener('fetch', (event) => {
  if (event.request.method !== 'GET') return;
  event.respondWith(caches.open(CACHE).then(async (cache) => {
    const kept = await cache.match(event.request, { ignoreSearch: true })
      || (event.request.mode === 'navigate' ? await cache.match('./') : undefined);
    return kept || fetch(event.request);
  }));
});
";

/// The page, loading the module as `script` says. The canvas takes every touch
/// (`touch-action: none`): otherwise the browser claims a finger's drag as a scroll and a
/// pinch as the page's zoom, and the explorer's own (W turned, the diagram panned or zoomed)
/// never happen.
#[must_use]
pub fn html(script: &Script<'_>) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<meta name=\"viewport\" \
         content=\"width=device-width, initial-scale=1\">\n<title>{TITLE}</title>\n{installable}<style>\n\
         html, body {{ margin: 0; padding: 0; width: 100%; height: 100%; overflow: hidden; \
         background: #f8f8f8; }}\ncanvas {{ position: absolute; top: 0; left: 0; width: 100%; \
         height: 100%; display: block; touch-action: none; }}\n#{LOADING_ID} {{ position: absolute; top: 45%; \
         width: 100%; text-align: center; font: 20px sans-serif; color: #333; }}\n\
         #{LOADING_ID}.failed {{ color: #a00000; }}\n{overlay_style}{CONTROLS_CSS}</style>\n</head>\n\
         <body>\n<section id=\"{CONTROLS_ID}\"></section>\n<canvas id=\"{CANVAS_ID}\"></canvas>\n<p \
         id=\"{LOADING_ID}\">…</p>\n{overlay}<script \
         type=\"module\">\n{}</script>\n</body>\n</html>\n",
        bootstrap(script).replace("</script", "<\\/script"),
        installable = installable_head(script),
        overlay_style = overlay_style(),
        overlay = overlay_elements(),
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
        // The served page is installable; the single file stays as it was.
        assert!(beside.contains("<link rel=\"manifest\" href=\"manifest.webmanifest\">"));
        assert!(beside.contains("serviceWorker.register(\"service-worker.js\")"));
        assert!(!inlined.contains("manifest") && !inlined.contains("serviceWorker"));
        // Both show a panic over the page and offer a tab of their own inside another page.
        for page in [&beside, &inlined] {
            assert!(page.contains("<div id=\"crashed\" role=\"alert\""));
            assert!(page.contains("window.refractionCrashed = "));
            assert!(page.contains("<a id=\"new-tab\""));
            assert!(
                page.contains("\"de\": { loading:") && page.contains("crashed: \"Der Explorer")
            );
        }
    }

    #[test]
    fn the_manifest_names_the_app_its_icons_and_where_it_starts() {
        let manifest: serde_json::Value = serde_json::from_str(&manifest()).unwrap();
        assert_eq!(manifest["name"], TITLE);
        assert_eq!(manifest["start_url"], "./");
        assert_eq!(manifest["display"], "standalone");
        let sizes: Vec<_> = manifest["icons"]
            .as_array()
            .unwrap()
            .iter()
            .map(|icon| icon["sizes"].as_str().unwrap().to_owned())
            .collect();
        assert_eq!(sizes, ["192x192", "512x512"]);
    }

    #[test]
    fn the_service_worker_caches_the_build_under_its_name_and_drops_the_others() {
        let worker = service_worker("0123abcd", &["index.html", "refraction_web_bg.wasm"]);
        assert!(worker.contains("const CACHE = \"refraction-explorer-0123abcd\";"));
        assert!(worker.contains("[\"./\", \"index.html\", \"refraction_web_bg.wasm\"]"));
        assert!(worker.contains("name.startsWith(\"refraction-explorer-\") && name !== CACHE"));
        assert_ne!(
            worker,
            service_worker("0123abce", &["index.html", "refraction_web_bg.wasm"]),
            "another build, another worker (the browser installs it)"
        );
    }
}
