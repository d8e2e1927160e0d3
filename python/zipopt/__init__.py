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
"""

import ctypes
import math
import os

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
    ("zipopt_scene_forces", _I, [_P, _DP, _I]),
    ("zipopt_scene_set_forces", _I, [_P, _DP, _I, _S, _Z]),
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
        err = ctypes.create_string_buffer(_ERR)
        if text:
            h = _lib.zipopt_scene_load_string(source.encode(), (name or "<string>").encode(),
                                              err, _ERR)
        else:
            h = _lib.zipopt_scene_load(os.fspath(source).encode(), err, _ERR)
        if not h:
            raise ZipoptError(err.value.decode(errors="replace"))
        self._h = h
        if forces is not None:
            self.forces = forces

    def close(self):
        if getattr(self, "_h", None):
            _lib.zipopt_scene_free(self._h)
            self._h = None

    __del__ = close

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    @property
    def name(self):
        return _lib.zipopt_scene_name(self._h).decode()

    @property
    def sections(self):
        return _lib.zipopt_scene_sections(self._h)

    @property
    def links(self):
        return _lib.zipopt_scene_links(self._h)

    @property
    def forces(self):
        """N, one per section."""
        return _doubles(_lib.zipopt_scene_forces, self._h, self.sections)

    @forces.setter
    def forces(self, values):
        f = np.ascontiguousarray(values, dtype=float).ravel()
        err = ctypes.create_string_buffer(_ERR)
        if _lib.zipopt_scene_set_forces(self._h, f.ctypes.data_as(_DP), len(f), err, _ERR):
            raise ZipoptError(err.value.decode(errors="replace"))

    def simulate(self):
        """One run of the current forces with the scene's [solver] settings."""
        err = ctypes.create_string_buffer(_ERR)
        h = _lib.zipopt_simulate(self._h, err, _ERR)
        if not h:
            raise ZipoptError(err.value.decode(errors="replace"))
        try:
            return Run(h)
        finally:
            _lib.zipopt_run_free(h)

    def search(self, max_evals=0, seed=-1, progress=None):
        """The fastest survivable schedule; max_evals <= 0 and seed < 0 take the scene's.
        progress(evals, wall_s, found, time, forces, improved) is called now and then; a true
        return stops the search, which answers with the best so far (interrupted); an exception
        it raises stops the search and is raised again here."""
        state = {"error": None}

        def on_progress(_user, evals, wall_s, found, time, force, n, improved):
            try:
                f = np.array(force[:n], dtype=float)
                return 1 if progress(evals, wall_s, bool(found), time, f, bool(improved)) else 0
            except BaseException as e:  # raised again once the library returns
                state["error"] = e
                return 1

        cb = _PROGRESS(on_progress) if progress else _PROGRESS()
        err = ctypes.create_string_buffer(_ERR)
        h = _lib.zipopt_search_run(self._h, int(max_evals), int(seed), cb, None, None, err, _ERR)
        if state["error"] is not None:
            if h:
                _lib.zipopt_search_free(h)
            raise state["error"]
        if not h:
            raise ZipoptError(err.value.decode(errors="replace"))
        try:
            return Search(h, self.sections)
        finally:
            _lib.zipopt_search_free(h)


class Run:
    """One simulation's result, copied out of the library.

    outcome ("finished", "died", "stalled"), stall (why it stalled, else ""), every number of
    zipopt_run_get as an attribute (time, x, speed, died_link, kinks, e_initial, e_final,
    w_drive, w_damp, e_impulse, energy_residual, ...), max_angles (rad per link), crossings (a
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
    """A search's answer: forces (N per section), found, time (s), evals, interrupted, ... (every
    number of zipopt_search_get as an attribute)."""

    def __init__(self, h, nsec):
        self.numbers = {k: _lib.zipopt_search_get(h, k.encode())
                        for k in _keys(_lib.zipopt_search_key)}
        for k, v in self.numbers.items():
            setattr(self, k, v)
        for k in ("found", "interrupted", "base_found"):
            setattr(self, k, bool(self.numbers[k]))
        self.evals = int(self.evals)
        self.forces = _doubles(_lib.zipopt_search_forces, h, nsec)

    def __repr__(self):
        t = f"{self.time:.6f} s" if self.found and not math.isnan(self.time) else "none survives"
        return f"<zipopt.Search {t}, forces {self.forces.tolist()}, {self.evals} simulations>"


def simulate(scene, forces=None):
    """Simulates a scene file (or a Scene) with its forces or the ones given (N per section)."""
    if isinstance(scene, Scene):
        if forces is not None:
            scene.forces = forces
        return scene.simulate()
    with Scene(scene, forces=forces) as s:
        return s.simulate()


def search(scene, max_evals=0, seed=-1, progress=None):
    """Searches a scene file (or a Scene) for its fastest survivable schedule (Search)."""
    if isinstance(scene, Scene):
        return scene.search(max_evals, seed, progress)
    with Scene(scene) as s:
        return s.search(max_evals, seed, progress)
