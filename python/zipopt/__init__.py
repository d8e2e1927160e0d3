"""zipopt from Python: simulate a scene and search for its fastest survivable drive.

A thin ctypes layer over libzipopt.so (include/zipopt.h); units are SI and radians.

    import zipopt
    r = zipopt.simulate("config/seed.ini", forces=[10, 10, 10])
    r.outcome, r.time, r.trajectory["x"]
    best = zipopt.search("config/seed.ini", max_evals=2000, progress=print)

The library is found through the environment variable ZIPOPT_LIB (a path), else next to this
module, else in the library folder of the prefix the module was installed into, else by the
system loader (libzipopt.so.0). example_scene("seed.ini") finds the example scenes the same
way (the repository's config/ or the installed share/zipopt/scenes/).

Re-entrancy: a progress function runs inside the library's search, which holds the library's
one lock (libmatheval and NLopt keep process-wide state). From inside it, loading a scene or
starting a search would wait for that lock forever, so both raise ValueError there; so do
closing, re-forcing, simulating or searching the Scene being searched. Simulating another
Scene is fine. Other threads may load and search; they wait their turn.

Bad arguments raise ValueError before anything reaches the library: a closed Scene, a NUL
byte in scene text, a name or a path (C would cut the text there), and whole numbers (max_evals,
seed) outside a C long (they would wrap).
"""

import ctypes
import math
import os
import threading

import numpy as np

__all__ = ["Scene", "Run", "Search", "ZipoptError", "simulate", "search", "library_version",
           "example_scene"]

_SONAME = "libzipopt.so.0"
_ERR = 8192  # bytes of error text: every problem of a scene, one per line


class ZipoptError(Exception):
    """A scene or a run zipopt refused; str() is its message, file:line: [section] key: ..."""


_HERE = os.path.dirname(os.path.abspath(__file__))


def _installed(name):
    """A folder of the installation, relative to this module (the install writes _install.py:
    the module, the library and the data move together under any prefix); None from a source
    tree."""
    try:
        from . import _install
    except ImportError:
        return None
    return os.path.normpath(os.path.join(_HERE, getattr(_install, name)))


def _load_library():
    path = os.environ.get("ZIPOPT_LIB")
    if path:
        return ctypes.CDLL(path)
    for folder in (_HERE, _installed("LIBDIR")):
        if folder and os.path.exists(os.path.join(folder, _SONAME)):
            return ctypes.CDLL(os.path.join(folder, _SONAME))
    return ctypes.CDLL(_SONAME)


def example_scene(name):
    """The path of one of zipopt's example scenes ("seed.ini", "human.ini", ...): the
    installed share/zipopt/scenes/, or config/ of the source tree this module lies in."""
    for folder in (_installed("SCENEDIR"), os.path.join(_HERE, "..", "..", "config")):
        if folder and os.path.isfile(os.path.join(folder, name)):
            return os.path.normpath(os.path.join(folder, name))
    raise ZipoptError("no example scene %r next to this zipopt module" % name)


_lib = _load_library()
_P = ctypes.c_void_p
_D = ctypes.c_double
_DP = ctypes.POINTER(ctypes.c_double)
_S = ctypes.c_char_p
_I = ctypes.c_int
_Z = ctypes.c_size_t
_PROGRESS = ctypes.CFUNCTYPE(_I, _P, ctypes.c_long, _D, _I, _D, _DP, _I, _I)

for _name, _res, _args in [
    ("zipopt_version", _S, []),
    ("zipopt_scene_load", _P, [_S, _S, _Z]),
    ("zipopt_scene_load_string", _P, [_S, _S, _S, _Z]),
    ("zipopt_scene_free", None, [_P]),
    ("zipopt_scene_name", _S, [_P]),
    ("zipopt_scene_sections", _I, [_P]),
    ("zipopt_scene_links", _I, [_P]),
    ("zipopt_scene_params", _I, [_P]),
    ("zipopt_scene_param_label", _I, [_P, _I, _S, _Z]),
    ("zipopt_scene_param_unit", _S, [_P]),
    ("zipopt_scene_param_bounds", _I, [_P, _DP, _DP, _I]),
    ("zipopt_scene_forces", _I, [_P, _DP, _I]),
    ("zipopt_scene_set_forces", _I, [_P, _DP, _I, _S, _Z]),
    ("zipopt_scene_load_schedule", _I, [_P, _S, _S, _Z]),
    ("zipopt_simulate", _P, [_P, _S, _Z]),
    ("zipopt_run_free", None, [_P]),
    ("zipopt_run_outcome", _I, [_P]),
    ("zipopt_outcome_name", _S, [_I]),
    ("zipopt_run_stall", _S, [_P]),
    ("zipopt_run_get", _D, [_P, _S]),
    ("zipopt_run_key", _S, [_I]),
    ("zipopt_run_max_angles", _I, [_P, _DP, _I]),
    ("zipopt_run_kinks", _I, [_P, _DP, _I]),
    ("zipopt_run_rows", _I, [_P]),
    ("zipopt_run_columns", _I, [_P]),
    ("zipopt_run_column", _S, [_P, _I]),
    ("zipopt_run_trajectory", _DP, [_P]),
    ("zipopt_gradient", _I, [_P, _DP, _DP, _I, ctypes.POINTER(_I), _S, _Z]),
    ("zipopt_gradient_limits", _I, [_P, _DP, _I, ctypes.POINTER(_I), _S, _Z]),
    ("zipopt_limit_key", _S, [_I]),
    ("zipopt_search_run", _P, [_P, ctypes.c_long, ctypes.c_long, _PROGRESS, _P,
                               ctypes.POINTER(ctypes.c_int), _S, _Z]),
    ("zipopt_search_free", None, [_P]),
    ("zipopt_search_get", _D, [_P, _S]),
    ("zipopt_search_key", _S, [_I]),
    ("zipopt_search_forces", _I, [_P, _DP, _I]),
]:
    _f = getattr(_lib, _name)
    _f.restype = _res
    _f.argtypes = _args


_LONG_BITS = 8 * ctypes.sizeof(ctypes.c_long)
_in_progress = threading.local()  # .depth: progress functions running in this thread


def _c_long(name, value):
    """value as a C long, or ValueError: ctypes would wrap it silently."""
    if isinstance(value, bool) or not isinstance(value, int):
        try:
            value = value.__index__()
        except AttributeError:
            raise ValueError(f"{name} must be a whole number, not {value!r}") from None
    if not -(1 << (_LONG_BITS - 1)) <= value < (1 << (_LONG_BITS - 1)):
        raise ValueError(f"{name} = {value} does not fit a C long ({_LONG_BITS} bits)")
    return value


def _c_text(what, text):
    """text as bytes for C, or ValueError when a NUL byte would cut it short there."""
    data = text if isinstance(text, bytes) else str(text).encode()
    at = data.find(b"\0")
    if at >= 0:
        raise ValueError(f"{what} contains a NUL byte at {at}; C would stop there")
    return data


def _not_in_progress(what):
    if getattr(_in_progress, "depth", 0):
        raise ValueError(f"{what} from inside a progress function: the library's search holds "
                         "its lock there (see the module's notes on re-entrancy)")


def library_version():
    """The loaded library's version, e.g. "0.1.0"."""
    return _lib.zipopt_version().decode()


def _keys(fn):
    out, i = [], 0
    while True:
        k = fn(i)
        if k is None:
            return out
        out.append(k.decode())
        i += 1


def _doubles(fn, handle, n):
    buf = (ctypes.c_double * max(n, 1))()
    fn(handle, buf, n)
    return np.array(buf[:n], dtype=float)


class Scene:
    """A loaded scene (a file path, or scene text with text=True); forces override [drive]."""

    def __init__(self, source, forces=None, text=False, name=None):
        self._h = None
        self._searching = False
        _not_in_progress("loading a scene")
        err = ctypes.create_string_buffer(_ERR)
        if text:
            h = _lib.zipopt_scene_load_string(_c_text("the scene text", source),
                                              _c_text("the name", name or "<string>"), err, _ERR)
        else:
            h = _lib.zipopt_scene_load(_c_text("the path", os.fsencode(source)), err, _ERR)
        if not h:
            raise ZipoptError(err.value.decode(errors="replace"))
        self._h = h
        if forces is not None:
            self.forces = forces

    def close(self):
        """Frees the scene; later use raises ValueError. Not while it is being searched."""
        if getattr(self, "_searching", False):
            raise ValueError("cannot close a Scene while it is being searched")
        if getattr(self, "_h", None):
            _lib.zipopt_scene_free(self._h)
            self._h = None

    def __del__(self):
        if not getattr(self, "_searching", False):
            self.close()

    def _handle(self, changes=False):
        """The library's handle, or ValueError for a closed Scene (or one being searched, when
        the call changes or runs it)."""
        if not getattr(self, "_h", None):
            raise ValueError("the Scene is closed")
        if changes and self._searching:
            raise ValueError("the Scene is being searched: its forces cannot change and it "
                             "cannot run until the search returns")
        return self._h

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def name(self):
        """[scene] name, or the file's stem; "" when neither gives one."""
        return _lib.zipopt_scene_name(self._handle()).decode()

    @property
    def sections(self):
        return _lib.zipopt_scene_sections(self._handle())

    @property
    def links(self):
        return _lib.zipopt_scene_links(self._handle())

    @property
    def params(self):
        """How many parameters the drive schedule has (one force per section, N, for the
        per-section constants of [drive] forces)."""
        return _lib.zipopt_scene_params(self._handle())

    @property
    def param_labels(self):
        """Each parameter's name: "section 1", "section 2", ..."""
        h, out = self._handle(), []
        for k in range(self.params):
            buf = ctypes.create_string_buffer(_lib.zipopt_scene_param_label(h, k, None, 0) + 1)
            _lib.zipopt_scene_param_label(h, k, buf, len(buf))
            out.append(buf.value.decode())
        return out

    @property
    def param_unit(self):
        """The unit of the parameters ("N")."""
        return _lib.zipopt_scene_param_unit(self._handle()).decode()

    @property
    def bounds(self):
        """The search's bounds of each parameter ([drive] min, max): (lo, hi) arrays."""
        n = self.params
        lo, hi = (ctypes.c_double * max(n, 1))(), (ctypes.c_double * max(n, 1))()
        _lib.zipopt_scene_param_bounds(self._handle(), lo, hi, n)
        return np.array(lo[:n], dtype=float), np.array(hi[:n], dtype=float)

    @property
    def forces(self):
        """The schedule's parameters (params of them): N, one per section, for [drive] forces."""
        return _doubles(_lib.zipopt_scene_forces, self._handle(), self.params)

    @forces.setter
    def forces(self, values):
        h = self._handle(changes=True)
        f = np.ascontiguousarray(values, dtype=float).ravel()
        err = ctypes.create_string_buffer(_ERR)
        if _lib.zipopt_scene_set_forces(h, f.ctypes.data_as(_DP), len(f), err, _ERR):
            raise ZipoptError(err.value.decode(errors="replace"))

    def load_schedule(self, path):
        """Lays a schedule file (the search's schedule.ini: [drive] forces) over the forces,
        as `zipopt simulate --schedule` does; a bad file raises ZipoptError, forces unchanged."""
        h = self._handle(changes=True)
        err = ctypes.create_string_buffer(_ERR)
        if _lib.zipopt_scene_load_schedule(h, _c_text("the path", os.fsencode(path)), err, _ERR):
            raise ZipoptError(err.value.decode(errors="replace"))

    def simulate(self):
        """One run of the current forces with the scene's [solver] settings."""
        sh = self._handle(changes=True)
        err = ctypes.create_string_buffer(_ERR)
        h = _lib.zipopt_simulate(sh, err, _ERR)
        if not h:
            raise ZipoptError(err.value.decode(errors="replace"))
        try:
            return Run(h)
        finally:
            _lib.zipopt_run_free(h)

    def gradient(self):
        """The exact derivatives of the current forces' run (`zipopt simulate --gradient`),
        per schedule parameter: a dict with time (s per N), margin_angle (deg per N), smooth
        (False where the run meets a point where it is not differentiable), limits ({key:
        derivatives} for each [limits] value the scene sets, in its unit per N; None where it
        has none there, e.g. the arrival speed of a ride that did not finish) and
        limits_smooth ({key: whether that one is differentiable there})."""
        sh = self._handle(changes=True)
        n = max(self.params, 1)
        dtime, dmargin = (ctypes.c_double * n)(), (ctypes.c_double * n)()
        smooth = _I()
        err = ctypes.create_string_buffer(_ERR)
        np_ = _lib.zipopt_gradient(sh, dtime, dmargin, n, ctypes.byref(smooth), err, _ERR)
        if np_ < 0:
            raise ZipoptError(err.value.decode(errors="replace"))
        keys = _keys(_lib.zipopt_limit_key)
        rows, lsmooth = (ctypes.c_double * (n * len(keys)))(), (_I * len(keys))()
        if _lib.zipopt_gradient_limits(sh, rows, n, lsmooth, err, _ERR) < 0:
            raise ZipoptError(err.value.decode(errors="replace"))
        limits, limits_smooth = {}, {}
        for i, k in enumerate(keys):
            row = np.array(rows[i * n:i * n + np_], dtype=float)
            if not np.all(np.isnan(row)):
                limits[k] = row
                limits_smooth[k] = bool(lsmooth[i])
        return {"time": np.array(dtime[:np_], dtype=float),
                "margin_angle": np.array(dmargin[:np_], dtype=float),
                "smooth": bool(smooth.value), "limits": limits, "limits_smooth": limits_smooth}

    def search(self, max_evals=0, seed=-1, progress=None):
        """The fastest survivable schedule; max_evals <= 0 and seed < 0 take the scene's.
        progress(evals, wall_s, found, time, forces, improved) is called now and then; a true
        return stops the search, which answers with the best so far (interrupted); an exception
        it raises stops the search and is raised again here."""
        state = {"error": None}

        def on_progress(_user, evals, wall_s, found, time, force, n, improved):
            try:
                f = np.array(force[:n], dtype=float)
                _in_progress.depth = getattr(_in_progress, "depth", 0) + 1
                try:
                    stop = progress(evals, wall_s, bool(found), time, f, bool(improved))
                finally:
                    _in_progress.depth -= 1
                return 1 if stop else 0
            except BaseException as e:  # raised again once the library returns
                state["error"] = e
                return 1

        max_evals, seed = _c_long("max_evals", max_evals), _c_long("seed", seed)
        _not_in_progress("a search")
        sh = self._handle(changes=True)
        cb = _PROGRESS(on_progress) if progress else _PROGRESS()
        err = ctypes.create_string_buffer(_ERR)
        self._searching = True
        try:
            h = _lib.zipopt_search_run(sh, max_evals, seed, cb, None, None, err, _ERR)
        finally:
            self._searching = False
        if state["error"] is not None:
            if h:
                _lib.zipopt_search_free(h)
            raise state["error"]
        if not h:
            raise ZipoptError(err.value.decode(errors="replace"))
        try:
            return Search(h, self.params)
        finally:
            _lib.zipopt_search_free(h)


class Run:
    """One simulation's result, copied out of the library.

    outcome ("finished", "died", "stalled"), stall (why it stalled, else ""), every number of
    zipopt_run_get as an attribute (time, x, speed, died_link, kinks, e_initial, e_final,
    w_drive, w_damp, e_impulse, energy_residual, ..., drive_peak_power, drive_energy,
    drive_time_at_cap), max_angles (rad per link), crossings (a
    structured array: t, x, from, to, impulse, energy_lost) and trajectory (a dict of numpy
    columns: t, section, x, y, speed, theta1.., omega1.., phi1.., kinetic, potential,
    drive_work, damper_work, impulse_loss).
    """

    def __init__(self, h):
        self.outcome = _lib.zipopt_outcome_name(_lib.zipopt_run_outcome(h)).decode()
        self.stall = _lib.zipopt_run_stall(h).decode()
        self.numbers = {k: _lib.zipopt_run_get(h, k.encode()) for k in _keys(_lib.zipopt_run_key)}
        for k, v in self.numbers.items():
            setattr(self, k, v)
        self.died_link = int(self.died_link)
        self.kinks = int(self.kinks)
        nlink = _lib.zipopt_run_max_angles(h, None, 0)
        self.max_angles = _doubles(_lib.zipopt_run_max_angles, h, nlink)
        nk = _lib.zipopt_run_kinks(h, None, 0)
        buf = (ctypes.c_double * max(6 * nk, 1))()
        _lib.zipopt_run_kinks(h, buf, nk)
        rows = np.array(buf[:6 * nk], dtype=float).reshape(nk, 6)
        names = ["t", "x", "from", "to", "impulse", "energy_lost"]
        self.crossings = np.rec.fromarrays(rows.T, names=names) if nk else np.recarray(
            0, dtype=[(n, float) for n in names])
        nrow, ncol = _lib.zipopt_run_rows(h), _lib.zipopt_run_columns(h)
        data = np.ctypeslib.as_array(_lib.zipopt_run_trajectory(h), shape=(nrow * ncol,)).copy()
        data = data.reshape(nrow, ncol)
        self.trajectory = {_lib.zipopt_run_column(h, j).decode(): data[:, j] for j in range(ncol)}

    def __repr__(self):
        return f"<zipopt.Run {self.outcome} at t = {self.time:.6f} s, x = {self.x:.3f} m>"


class Search:
    """A search's answer: forces (the schedule's parameters: N per section), found, time (s),
    evals, interrupted, ... (every number of zipopt_search_get as an attribute)."""

    def __init__(self, h, nparam):
        self.numbers = {k: _lib.zipopt_search_get(h, k.encode())
                        for k in _keys(_lib.zipopt_search_key)}
        for k, v in self.numbers.items():
            setattr(self, k, v)
        for k in ("found", "interrupted", "base_found"):
            setattr(self, k, bool(self.numbers[k]))
        self.evals = int(self.evals)
        self.forces = _doubles(_lib.zipopt_search_forces, h, nparam)

    def __repr__(self):
        t = f"{self.time:.6f} s" if self.found and not math.isnan(self.time) else "none survives"
        return f"<zipopt.Search {t}, forces {self.forces.tolist()}, {self.evals} simulations>"


def simulate(scene, forces=None, schedule=None):
    """Simulates a scene file (or a Scene) with its forces, or a schedule file's (schedule.ini),
    or the forces given (N per section), the last given winning as on the command line."""
    if isinstance(scene, Scene):
        if schedule is not None:
            scene.load_schedule(schedule)
        if forces is not None:
            scene.forces = forces
        return scene.simulate()
    with Scene(scene) as s:
        return simulate(s, forces, schedule)


def search(scene, max_evals=0, seed=-1, progress=None):
    """Searches a scene file (or a Scene) for its fastest survivable schedule (Search)."""
    if isinstance(scene, Scene):
        return scene.search(max_evals, seed, progress)
    with Scene(scene) as s:
        return s.search(max_evals, seed, progress)
