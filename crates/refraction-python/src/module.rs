//! The Python module `refraction_check._native` (PyO3): `check()` and the `Checked` it
//! returns. Everything past reading Python's objects is the crate's own code, tested in Rust.

use numpy::{PyArray1, PyReadonlyArrayDyn, PyUntypedArrayMethods as _};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use refraction_check::fields::Kind;
use refraction_check::{Dialect, Value};
use refraction_tools::Precision;

use crate::ArgumentError;
use crate::arrays::{self, Array, Column};
use crate::calls::{self, Calls};
use crate::options::{self, Given, Normal};
use crate::report::Report;

impl From<ArgumentError> for PyErr {
    fn from(error: ArgumentError) -> Self {
        PyValueError::new_err(error.to_string())
    }
}

/// `value`'s `repr`, for a message that quotes what was given.
fn repr(value: &Bound<'_, PyAny>) -> String {
    value
        .repr()
        .map_or_else(|_| String::new(), |r| r.to_string())
}

/// Why `argument` does not read as numbers: numpy's own words, or the kind of values found.
fn not_numbers(argument: &str, reason: &impl ToString) -> ArgumentError {
    ArgumentError::NotNumbers {
        argument: argument.to_owned(),
        reason: reason.to_string(),
    }
}

/// Whether `value` is a Dr.Jit array of vectors (Mitsuba's `Vector3f` in a vectorised
/// variant), which numpy sees with the components first: `(3, N)`. Dr.Jit's tensors are shaped
/// as numpy's arrays are.
fn is_drjit_vectors(py: Python<'_>, value: &Bound<'_, PyAny>) -> PyResult<bool> {
    // Only a program that imported Dr.Jit can hand over its arrays.
    let drjit = py
        .import("sys")?
        .getattr("modules")?
        .call_method1("get", ("drjit",))?;
    if drjit.is_none() {
        return Ok(false);
    }
    let test = |name: &str| -> PyResult<bool> { drjit.getattr(name)?.call1((value,))?.extract() };
    Ok(test("is_array_v")? && !test("is_tensor_v")?)
}

/// A list or tuple of vectors with `None` items (a call that logged nothing), with each
/// `None` made three NaNs, so that numpy reads the rest as rows of three.
fn vectors_without_none<'py>(value: &Bound<'py, PyAny>) -> PyResult<Option<Bound<'py, PyList>>> {
    let items: Vec<Bound<'py, PyAny>> = if let Ok(list) = value.cast::<PyList>() {
        list.iter().collect()
    } else if let Ok(tuple) = value.cast::<PyTuple>() {
        tuple.iter().collect()
    } else {
        return Ok(None);
    };
    if !items.iter().any(PyAnyMethods::is_none) {
        return Ok(None);
    }
    let nan = [f64::NAN; 3];
    let rows: Vec<Bound<'py, PyAny>> = items
        .into_iter()
        .map(|item| {
            if item.is_none() {
                nan.into_pyobject(item.py()).map(Bound::into_any)
            } else {
                Ok(item)
            }
        })
        .collect::<PyResult<_>>()?;
    PyList::new(value.py(), rows).map(Some)
}

/// An argument's numbers as `f64` through numpy's `asarray` (`NumPy`, `Dr.Jit` and CPU torch
/// arrays, lists, numbers), with whether they were `float32` or narrower.
fn numbers(
    py: Python<'_>,
    argument: &str,
    kind: Kind,
    value: &Bound<'_, PyAny>,
) -> Result<(Array, bool), ArgumentError> {
    let read = || -> PyResult<Result<(Array, bool), ArgumentError>> {
        let numpy = py.import("numpy")?;
        let vectors = matches!(kind, Kind::Vector | Kind::VectorOrNull);
        let given = match vectors_without_none(value)? {
            Some(list) if vectors => list.into_any(),
            _ => value.clone(),
        };
        let raw = match numpy.call_method1("asarray", (&given,)) {
            Ok(raw) => raw,
            Err(e) => return Ok(Err(not_numbers(argument, &e))),
        };
        let dtype = raw.getattr("dtype")?;
        let code: String = dtype.getattr("kind")?.extract()?;
        if !matches!(code.as_str(), "b" | "i" | "u" | "f" | "O") {
            return Ok(Err(not_numbers(argument, &dtype.str()?)));
        }
        let narrow = code == "f" && dtype.getattr("itemsize")?.extract::<usize>()? <= 4;
        let wide = match raw.call_method1("astype", (numpy.getattr("float64")?,)) {
            Ok(wide) => wide,
            Err(e) => return Ok(Err(not_numbers(argument, &e))),
        };
        let wide: PyReadonlyArrayDyn<'_, f64> = wide.extract()?;
        let array = Array {
            shape: wide.shape().to_vec(),
            values: wide.as_array().iter().copied().collect(),
            components_first: vectors && is_drjit_vectors(py, value)?,
        };
        Ok(Ok((array, narrow)))
    };
    read().unwrap_or_else(|e| Err(not_numbers(argument, &e)))
}

/// A word field's column (`path`, a call's own `precision` or `convention`): one word for every
/// call, numbers as words, or one item a call (`None` where nothing was logged).
fn words(
    py: Python<'_>,
    argument: &str,
    value: &Bound<'_, PyAny>,
) -> Result<Column, ArgumentError> {
    if let Ok(word) = value.cast::<PyString>() {
        return Ok(Column::Every(Value::Label(word.to_string())));
    }
    if let Ok((array, _)) = numbers(py, argument, Kind::Label, value) {
        return arrays::column(Kind::Label, argument, &array);
    }
    let items = value.try_iter().map_err(|e| not_numbers(argument, &e))?;
    let rows = items
        .map(|item| {
            let item = item.map_err(|e| not_numbers(argument, &e))?;
            Ok((!item.is_none()).then(|| item.to_string()))
        })
        .collect::<Result<_, ArgumentError>>()?;
    Ok(arrays::labels(rows))
}

/// The calls' fields, each keyword's column read by its field's kind; whether any was f32.
fn calls(
    py: Python<'_>,
    dialect: Dialect,
    fields: &Bound<'_, PyDict>,
) -> Result<(Calls, bool), ArgumentError> {
    let (mut calls, mut narrow) = (Calls::new(dialect), false);
    for (key, value) in fields {
        let argument = key.to_string();
        let (field, kind) = calls::field(dialect, &argument)?;
        let column = if value.is_none() {
            Column::Every(Value::Null)
        } else if kind == Kind::Label {
            words(py, &argument, &value)?
        } else {
            let (array, f32) = numbers(py, &argument, kind, &value)?;
            narrow |= f32;
            arrays::column(kind, &argument, &array)?
        };
        calls.add(field, &argument, column);
    }
    Ok((calls, narrow))
}

/// An index keyword (`inside`, `outside`) as a number.
fn index(
    argument: &'static str,
    value: Option<&Bound<'_, PyAny>>,
) -> Result<Option<f64>, ArgumentError> {
    value
        .map(|v| {
            v.extract::<f64>()
                .map_err(|_not_a_number| ArgumentError::Index {
                    argument,
                    value: repr(v),
                })
        })
        .transpose()
}

/// A word keyword (`renderer`, `api`), or `None`.
fn word(
    value: Option<&Bound<'_, PyAny>>,
    refused: impl Fn(String) -> ArgumentError,
) -> Result<Option<String>, ArgumentError> {
    value
        .map(|v| {
            v.cast::<PyString>()
                .map(ToString::to_string)
                .map_err(|_not_a_word| refused(repr(v)))
        })
        .transpose()
}

/// `normal`: an axis or a vector as a word, or three numbers.
fn normal(
    py: Python<'_>,
    value: Option<&Bound<'_, PyAny>>,
) -> Result<Option<Normal>, ArgumentError> {
    let Some(value) = value else { return Ok(None) };
    if let Ok(text) = value.cast::<PyString>() {
        return Ok(Some(Normal::Text(text.to_string())));
    }
    let refused = || ArgumentError::Normal { value: repr(value) };
    let (array, _) =
        numbers(py, "normal", Kind::Vector, value).map_err(|_not_numbers| refused())?;
    match array.values.as_slice() {
        &[x, y, z] if array.shape == [3] => Ok(Some(Normal::Vector([x, y, z]))),
        _ => Err(refused()),
    }
}

/// Splits a keyword that is an option when a word and a call's field otherwise (`precision`,
/// `convention`): the option's word, after adding the field's column to `fields`.
fn option_or_field<'py>(
    name: &str,
    value: Option<&Bound<'py, PyAny>>,
    fields: &Bound<'py, PyDict>,
) -> PyResult<Option<String>> {
    match value {
        Some(v) if v.is_instance_of::<PyString>() => Ok(Some(v.to_string())),
        Some(v) => fields.set_item(name, v).map(|()| None),
        None => Ok(None),
    }
}

/// Judges calls of a renderer's refraction held in arrays, and diagnoses them as one log, as
/// `check` (`check --api NAME`) does the same calls logged as JSON Lines.
///
/// `api` is `"glsl"` (or `"hlsl"`, `"wgsl"`, `"glm"`, `"glam"`), `"pbrt"`, `"rtiow"`,
/// `"mitsuba"`, or None for any renderer's own refraction. Every field a call of that API has
/// is a keyword of the same name (`wi`, `n`, `eta`, `wo` for Mitsuba; `I`, `N`, `eta`,
/// `result` for GLSL; `w`, `n`, `mu_i`, `mu_t`, `t_yours`, `ratio` without `api`...), and so
/// are the truth fields `from_`, `to`, `travel`, `entering`, `path`: vectors of shape `(N, 3)`
/// or `(3,)` (one for every call), numbers and flags of shape `(N,)` or one, anything numpy's
/// `asarray` takes (`NumPy`, `Dr.Jit`, torch on the CPU, lists). A row of NaN or a `None` logged
/// nothing, as `null` does on a JSON line. `check`'s options are keywords too: `inside`,
/// `outside`, `normal`, `convention`, `precision` (f32 when the arrays are float32), `renderer`.
///
/// Raises `ValueError`, naming the argument, for a shape, a type or a value that cannot be
/// used, and when no call can be judged for one reason (an argument left out).
#[pyfunction]
#[pyo3(signature = (api=None, *, inside=None, outside=None, normal=None, convention=None, precision=None, renderer=None, **fields))]
#[expect(
    clippy::too_many_arguments,
    reason = "Python's keywords, each one of `check`'s options"
)]
fn check<'py>(
    py: Python<'py>,
    api: Option<&Bound<'py, PyAny>>,
    inside: Option<&Bound<'py, PyAny>>,
    outside: Option<&Bound<'py, PyAny>>,
    normal: Option<&Bound<'py, PyAny>>,
    convention: Option<&Bound<'py, PyAny>>,
    precision: Option<&Bound<'py, PyAny>>,
    renderer: Option<&Bound<'py, PyAny>>,
    fields: Option<&Bound<'py, PyDict>>,
) -> PyResult<Checked> {
    let api = word(api, |name| ArgumentError::UnknownApi { name })?;
    let dialect = options::dialect(api.as_deref())?;
    // A copy: the caller's own dict (`check(**mine)`) is never changed.
    let fields = fields.map_or_else(|| Ok(PyDict::new(py)), |f| f.copy())?;
    let convention = option_or_field("convention", convention, &fields)?;
    let precision = option_or_field("precision", precision, &fields)?;
    let (calls, narrow) = calls(py, dialect, &fields)?;
    let given = Given {
        inside: index("inside", inside)?,
        outside: index("outside", outside)?,
        normal: self::normal(py, normal)?,
        convention,
        precision,
        renderer: word(renderer, |value| ArgumentError::UnknownWord {
            argument: "renderer",
            value,
            expected: options::RENDERERS,
        })?,
        arrays: narrow.then_some(Precision::F32),
    };
    let options = options::options(dialect, &given)?;
    let checked = py.detach(|| calls::check(&options, &calls))?;
    Ok(Checked {
        report: Report::new(checked),
    })
}

/// What `check()` found: one verdict per call, the tally and the diagnosis of all the calls
/// as one log.
#[pyclass(frozen, name = "Checked", module = "refraction_check")]
struct Checked {
    report: Report,
}

#[pymethods]
impl Checked {
    /// Whether each call is right: a numpy bool array (a sampled reflection is right; a call
    /// that could not be judged is not).
    #[getter]
    fn ok<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<bool>> {
        PyArray1::from_vec(py, self.report.ok())
    }

    /// Each call's code as `check` counts it: `ok`, `reflected (sampled)`, a mistake's code
    /// (`eta_inverted`), codes the call alone cannot tell apart joined by `|`, `unexplained`,
    /// a candidate's name without `api` (`wrong_side`), or `unreadable`: a numpy str array.
    #[getter]
    fn codes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("numpy")?
            .call_method1("asarray", (self.report.codes(),))
    }

    /// The mistakes that explain each call, the likeliest first: a list of lists of codes.
    #[getter]
    fn mistakes(&self) -> Vec<Vec<&'static str>> {
        self.report.mistakes()
    }

    /// The diagnosis of all the calls as one log: the dict `check --summary` writes
    /// (`lines`, `judged`, `ok`, `skipped`, `sampled`, `diagnosis`: the verdict first, each
    /// finding with its `code`, `lines`, `where` and `fix`).
    #[getter]
    fn summary<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("json")?
            .call_method1("loads", (self.report.summary_json(),))
    }

    /// Each call's answer as `check` writes its JSON line (`ok`, `matches`, `explanation`, the
    /// right `t`, `api_result`, `mistakes`, `alternatives`), as a dict; None where the call
    /// could not be judged (see `errors`).
    #[getter]
    fn answers<'py>(&self, py: Python<'py>) -> PyResult<Vec<Option<Bound<'py, PyAny>>>> {
        let loads = py.import("json")?.getattr("loads")?;
        self.report
            .answers()
            .into_iter()
            .map(|answer| answer.map(|a| loads.call1((a,))).transpose())
            .collect()
    }

    /// Why each call could not be judged (None for those judged), as `check` answers such a
    /// line.
    #[getter]
    fn errors(&self) -> Vec<Option<String>> {
        self.report.errors()
    }

    /// The calls counted by code, as `check` prints them: a dict.
    #[getter]
    fn tally<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let tally = PyDict::new(py);
        for (code, count) in self.report.tally() {
            tally.set_item(code, count)?;
        }
        Ok(tally)
    }

    /// The diagnosis in sentences, the verdict first, as `check` prints it.
    #[getter]
    fn diagnosis(&self) -> Vec<String> {
        self.report.sentences()
    }

    /// The verdict's code: `"none"` when every call is right, `"unchecked"` when nothing tells
    /// a right ratio from a wrong one, else the bug's code (`summary["diagnosis"][0]["code"]`).
    #[getter]
    fn verdict(&self) -> Option<&'static str> {
        self.report.verdict()
    }

    fn __len__(&self) -> usize {
        self.report.len()
    }

    fn __repr__(&self) -> String {
        self.report.text()
    }

    /// The short table a notebook shows.
    fn _repr_html_(&self) -> String {
        self.report.html()
    }
}

/// The diagnosis of a renderer's refraction, from its calls held in arrays.
#[pymodule]
mod _native {
    #[pymodule_export]
    use super::{Checked, check};

    #[pymodule_init]
    fn init(module: &pyo3::Bound<'_, pyo3::types::PyModule>) -> pyo3::PyResult<()> {
        use pyo3::types::PyModuleMethods as _;
        module.add("__version__", env!("CARGO_PKG_VERSION"))
    }
}
