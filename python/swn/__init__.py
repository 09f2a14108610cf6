"""Surface winding numbers (Feng, Gillespie and Crane, SIGGRAPH 2023) of curves on surface meshes.

numpy in, numpy out: ``winding_numbers(V, F, curves)`` solves once (triangle meshes, polygon meshes and
polygon soups), ``Solver(V, F)`` keeps a triangle mesh for many curves, ``read_mesh()``, ``read_curve()``
and ``load()`` are the readers of the ``swn`` tool, ``polylines_to_chain()`` and ``stamp_polylines()`` put
curves drawn off the mesh onto it, ``clean_face_selection()`` and ``clean_edge_selection()`` turn noisy
selections into regions. The manual is python/README.md in the source tree.

Conventions
-----------
* ``V``: (n, 3) coordinates; ``F``: (m, k) vertex indices (0-based), or a sequence of m polygons. An
  oriented 2-manifold triangle mesh (possibly with border) is solved as a mesh; anything else (polygons,
  nonmanifold edges or vertices, nonorientable gluings) by ``winding_numbers()`` as a polygon soup.
* Curves run along edges: either an integer array of k halfedges ``(source, target)``, shape (k, 2), or a
  sequence of vertex polylines (repeat the first vertex at the end to close a loop). ``multiplicities``
  gives one integer per halfedge, resp. per polyline (default 1); a negative one reverses it.
* Per-face outputs are in the order of ``F``; per-edge outputs in the order of ``edges``, an (E, 2) array
  of vertex pairs ``(a, b)``: a value ``c`` on edge ``(a, b)`` means ``c`` traversals from ``a`` to ``b``.
* Crossing an edge from its right to its left (seen from the side the faces' orientation points to),
  ``W`` increases by the curve's value there: the inside of a counter-clockwise loop is one higher. In
  every connected component the label covering the largest area is 0.
"""

import os
import warnings
from dataclasses import dataclass

import numpy as np

from . import _swn

__version__ = _swn.__version__
__all__ = ["winding_numbers", "Solver", "WindingNumbers", "read_mesh", "read_curve", "load", "polylines_to_chain",
           "stamp_polylines", "CurveOnMesh", "clean_face_selection", "clean_edge_selection", "CleanSelection",
           "LabelConfidence", "InputError", "MeshWarning", "LP_SOLVERS",
           "LINEAR_SOLVERS"]

#: the residual solvers compiled in (``lp_solver=``), the default first: "lemon" (multilevel minimum-cost
#: flow with an optimality certificate), "lemon-simplex" (LEMON's network simplex), "glpk" (simplex)
LP_SOLVERS = tuple(_swn.lp_solvers)
#: the sparse Cholesky solvers compiled in (``linear_solver=``), the default first: "cholmod" (the
#: package's supernodal factorization on CHOLMOD's analysis), "ldlt" (Eigen's SimplicialLDLT)
LINEAR_SOLVERS = tuple(_swn.linear_solvers)

#: Bad input in a file read by ``read_mesh()``, ``read_curve()`` or ``load()``: a ``ValueError`` whose
#: message is the tool's ``FILE:LINE: reason``; attributes ``file``, ``line`` (None when the problem is on
#: no line) and ``reason``.
InputError = _swn.InputError


class MeshWarning(UserWarning):
    """Something unusual in a mesh that is kept as it is (unreferenced or duplicated vertices, ...)."""


@dataclass(eq=False)
class LabelConfidence:
    """How close the runner-up of every region's label is (the library's ``Label_confidence``, paper Eq. 11).

    A region is a maximal set of faces connected across edges where the curves, G and the jump of W are all
    zero; its flip cost is the growth of Eq. 11's objective (lengths in mean interior edge lengths, input
    edges weighted by epsilon) when its label alone changes by one, infinite if neither direction is
    feasible. The second-best labeling flips the cheapest region that is not the largest of its component
    and covers at least 0.5 % of the area.
    """

    face_cost: np.ndarray     #: (m,) float64: the flip cost of every face's region
    region: np.ndarray        #: (m,) int64: the region of every face (an index into regions)
    regions: list             #: per region, a dict: label, faces, area, component, flip_cost, flip_delta, boundary_length, largest_in_component
    second_best_W: np.ndarray  #: (m,) int32: the second-best labeling (W where there is none)
    second_best_region: int   #: the region it flips, or None
    second_best_cost: float   #: its flip cost (inf when there is none)


@dataclass(eq=False)
class WindingNumbers:
    """The outputs of a solve (numpy arrays) and its report."""

    W: np.ndarray         #: (m,) int32: the winding number label of every face, in the order of F
    w: np.ndarray         #: (m, k) float64: w at corner c of face f (vertex F[f][c]); faces of mixed sizes: all
                          #: corners in one (sum of the sizes,) array, face by face; NaN at interior curve endpoints
    edges: np.ndarray     #: (E, 2) int64: the vertex pairs (a, b) the per-edge values refer to
    bounding: np.ndarray  #: (E,) int32: the closed completion of the bounding curves (the jumps of W)
    G: np.ndarray         #: (E,) int32: the nonbounding loops, closed
    g: np.ndarray         #: (E,) float64: the real-valued nonbounding chain
    report: dict          #: what the solve did: sizes, topology, residual problem, times in seconds
    polygon_soup: str = ""  #: why it was solved as a polygon soup ("" when solved as a triangle mesh)
    confidence: LabelConfidence = None  #: the per-region confidence (``confidence=True``; None otherwise)


@dataclass(eq=False)
class CurveOnMesh:
    """Curves put on the edges of the mesh they live on: read from files (``read_curve()``, ``load()``) or
    drawn off the mesh (``polylines_to_chain()``, ``stamp_polylines()``)."""

    V: np.ndarray               #: (n', 3) the mesh's vertices: the input's first, then those of the cut
    F: np.ndarray               #: (m', 3) its faces: the input's first (each cut face keeps one piece), then the new
    halfedges: np.ndarray       #: (k, 2) int64: the curves' halfedges (source, target)
    multiplicities: np.ndarray  #: (k,) int64: how many times the curves run along each of them (positive)
    info: dict                  #: vertices and faces added by the cut and the refinement, warnings, ...
    face_origin: np.ndarray     #: (m',) int64: the input face every face is a piece of (itself for faces not cut)


@dataclass(eq=False)
class CleanSelection:
    """A selection cleaned by ``clean_face_selection()`` or ``clean_edge_selection()``."""

    selected: np.ndarray  #: (m,) bool: the faces of the cleaned region, in the order of F
    bounding: np.ndarray  #: (E,) int32: its border as a closed chain on ``edges``, counter-clockwise around it
    edges: np.ndarray     #: (E, 2) int64: the vertex pairs the chain refers to (as ``Solver.edges``)
    report: dict          #: what the solve did (``curve_edges``: the selection's border kept, ``interior_endpoints``: the ends of its gaps)


def _warn(messages, stacklevel):
    for message in messages:
        warnings.warn(message, MeshWarning, stacklevel=stacklevel + 1)


def _integer_array(a, what):
    if a.size and a.dtype.kind not in "iu":
        raise TypeError(f"{what} must hold integers, not {a.dtype}")
    return a.astype(np.int64, copy=False)


def _curve_arrays(curves, multiplicities):
    """The curves as polylines: all vertices, the offsets of the polylines in them, one multiplicity each."""
    if isinstance(curves, np.ndarray):
        if curves.ndim != 2 or curves.shape[1] != 2:
            raise ValueError("curves given as an array must be halfedges of shape (k, 2), not of shape "
                             f"{curves.shape}; give vertex polylines as a list of sequences")
        vertices = _integer_array(curves, "curves").ravel()
        offsets = np.arange(0, vertices.size + 1, 2, dtype=np.int64)
    else:
        polylines = []
        for i, p in enumerate(curves):
            p = np.asarray(p)
            if p.ndim != 1:
                raise ValueError(f"curves[{i}] must be a sequence of vertex indices (a polyline), not of shape {p.shape}")
            polylines.append(_integer_array(p, f"curves[{i}]"))
        vertices = np.concatenate(polylines) if polylines else np.zeros(0, np.int64)
        offsets = np.zeros(len(polylines) + 1, np.int64)
        offsets[1:] = np.cumsum([p.size for p in polylines])
    n = offsets.size - 1
    if multiplicities is None:
        return vertices, offsets, np.ones(n, np.int64)
    m = _integer_array(np.asarray(multiplicities), "multiplicities")
    if m.ndim == 0:
        return vertices, offsets, np.full(n, m, np.int64)
    if m.shape != (n,):
        raise ValueError(f"multiplicities must have one value per curve ({n}), not shape {m.shape}")
    return vertices, offsets, m


def _boolean(value, name):
    if not isinstance(value, (bool, np.bool_)):
        raise ValueError(f"{name} must be True or False, not {value!r}")
    return bool(value)


def _choice(value, name, allowed):
    if value is None:
        return allowed[0]
    if value not in allowed:
        raise ValueError(f"{name} must be one of {', '.join(map(repr, allowed))} (compiled in), not {value!r}")
    return value


def _options(epsilon, lp_solver, linear_solver, reduced_residual, filter_nonbounding_loops, concurrency, verbose,
             anchor_face=None, confidence=False, completed_homology_class=False):
    """The settings of a solve, checked: ValueError naming the setting and its allowed values."""
    if anchor_face is not None and (isinstance(anchor_face, (bool, np.bool_)) or not isinstance(anchor_face, (int, np.integer))
                                    or anchor_face < 0):
        raise ValueError(f"anchor_face must be a face index (an integer >= 0) or None, not {anchor_face!r}")
    try:
        eps = float(epsilon)
    except (TypeError, ValueError):
        eps = None
    if eps is None or not np.isfinite(eps) or eps <= 0 or isinstance(epsilon, (bool, np.bool_)):
        raise ValueError(f"epsilon must be positive and finite, not {epsilon!r}")
    return {"epsilon": eps, "lp_solver": _choice(lp_solver, "lp_solver", LP_SOLVERS),
            "linear_solver": _choice(linear_solver, "linear_solver", LINEAR_SOLVERS),
            "reduced_residual": _boolean(reduced_residual, "reduced_residual"),
            "filter_nonbounding_loops": _boolean(filter_nonbounding_loops, "filter_nonbounding_loops"),
            "completed_homology_class": _boolean(completed_homology_class, "completed_homology_class"),
            "concurrency": _boolean(concurrency, "concurrency"), "verbose": _boolean(verbose, "verbose"),
            "anchor_face": -1 if anchor_face is None else int(anchor_face), "confidence": _boolean(confidence, "confidence")}


def _result(r, edges):
    c = r.get("confidence")
    return WindingNumbers(W=r["W"], w=r["w"], edges=edges, bounding=r["bounding"], G=r["G"], g=r["g"],
                          report=r["report"], polygon_soup=r.get("polygon_soup", ""),
                          confidence=None if c is None else LabelConfidence(**c))


def _dual_pairs(dual_chain):
    """The dual chain as a (k, 2) int64 array of face pairs (a, b): +1 from face a into face b."""
    if dual_chain is None:
        return np.zeros((0, 2), np.int64)
    if isinstance(dual_chain, np.ndarray):
        if dual_chain.ndim != 2 or dual_chain.shape[1] != 2:
            raise ValueError("dual_chain given as an array must be face pairs of shape (k, 2), not of shape "
                             f"{dual_chain.shape}; give face paths as a list of sequences")
        return np.ascontiguousarray(_integer_array(dual_chain, "dual_chain"))
    pairs = []
    for i, p in enumerate(dual_chain):
        p = _integer_array(np.asarray(p), f"dual_chain[{i}]")
        if p.ndim != 1:
            raise ValueError(f"dual_chain[{i}] must be a sequence of face indices (a path), not of shape {p.shape}")
        pairs.append(np.column_stack([p[:-1], p[1:]]))
    return np.ascontiguousarray(np.concatenate(pairs)) if pairs else np.zeros((0, 2), np.int64)


class Solver:
    """The triangle mesh (V, F) and the package's solver on it, for many curves on one mesh.

    The per-mesh work (tables, cotan weights, the Hodge step's harmonic basis, the factorized Laplacian of
    closed curves) is done once. ``linear_solver``: the sparse Cholesky solver, one of ``LINEAR_SOLVERS``
    (default: the first). Raises ``ValueError`` on an invalid mesh (index out of range, zero-area face,
    non-finite coordinate, no face) and on a surface that is not an oriented 2-manifold triangle mesh
    (polygons, nonmanifold edge or vertex, inconsistent orientation: ``winding_numbers()`` solves those as
    polygon soups). The mesh is copied: later changes to V and F do not reach the solver. Solves on one
    solver run one at a time; the GIL is released while they run.
    """

    def __init__(self, V, F, *, linear_solver=None):
        self._solver = _swn.Solver(V, F, _choice(linear_solver, "linear_solver", LINEAR_SOLVERS))
        self.edges = self._solver.edges
        self.edges.flags.writeable = False
        _warn(self._solver.warnings, 2)   # at the caller of Solver()

    @property
    def report(self):
        """The mesh part of the report (sizes, components, genus, border), from the construction."""
        return self._solver.report

    @property
    def number_of_vertices(self):
        return self._solver.number_of_vertices

    @property
    def number_of_faces(self):
        return self._solver.number_of_faces

    def solve(self, curves, multiplicities=None, *, epsilon=0.01, lp_solver=None, reduced_residual=False,
              filter_nonbounding_loops=True, anchor_face=None, confidence=False, concurrency=True, verbose=False,
              completed_homology_class=False):
        """Winding numbers of ``curves`` (halfedges (k, 2) or vertex polylines) on this mesh.

        The settings are those of ``winding_numbers()`` (the sparse solver is the solver's). Returns a
        ``WindingNumbers``. Raises ``ValueError`` on bad curves (a vertex out of range, consecutive vertices
        not joined by an edge, a curve on a border edge) and bad settings, and ``RuntimeError`` when a step
        of the solver fails, with the library's message.
        """
        vertices, offsets, m = _curve_arrays(curves, multiplicities)
        options = _options(epsilon, lp_solver, LINEAR_SOLVERS[0], reduced_residual, filter_nonbounding_loops,
                           concurrency, verbose, anchor_face, confidence, completed_homology_class)
        return _result(self._solver._solve(vertices, offsets, m, options), self.edges)


def winding_numbers(V, F, curves=None, multiplicities=None, *, dual_chain=None, soup=False, epsilon=0.01,
                    lp_solver=None, linear_solver=None, reduced_residual=False, filter_nonbounding_loops=True,
                    anchor_face=None, confidence=False, concurrency=True, verbose=False,
                    completed_homology_class=False):
    """Winding numbers of ``curves`` (and of ``dual_chain``) on the surface (V, F): one solve.

    ``F``: an (m, k) array or a sequence of polygons. An oriented 2-manifold triangle mesh is solved as a
    mesh (as ``Solver``); polygons, nonmanifold edges and vertices, nonorientable gluings, a ``dual_chain``
    or ``soup=True`` go through the library's ``polygon_soup_winding_numbers()``, with labels per input
    polygon (``polygon_soup`` in the result says why). ``curves``: halfedges (k, 2) or vertex polylines
    along the edges; ``dual_chain``: face pairs (k, 2), or face paths, each pair a jump of +1 from the first
    face into the second across the edge they share (the input of choice on nonorientable surfaces).

    Settings (the library's named parameters): ``epsilon`` (relative cost of jumps of the residual function
    across the curve, paper Eq. 11), ``lp_solver`` (one of ``LP_SOLVERS``), ``linear_solver`` (one of
    ``LINEAR_SOLVERS``), ``reduced_residual`` (the paper's Sec. 6 approximation),
    ``filter_nonbounding_loops`` (``False``: labels are the rounded jump-harmonic function, paper Fig. 27),
    ``anchor_face`` (a face whose label is 0 in its component, instead of the label covering the largest
    area), ``confidence`` (``True``: the result's ``confidence``, a ``LabelConfidence``; on a soup per
    input polygon), ``concurrency`` (``False``: the calling thread only), ``verbose`` (the steps on stderr),
    ``completed_homology_class`` (``True``: for a broken curve, the residual problem in the homology class of
    the curve with its gaps closed by shortest paths that continue the curve's direction at their ends, instead
    of the harmonic part's; off by default, see the manual's "Beyond Eq. 11").

    Returns a ``WindingNumbers``. Raises ``ValueError`` on bad input and bad settings and ``RuntimeError``
    when the solver fails, with the library's messages.
    """
    if curves is None and dual_chain is None:
        raise ValueError("no curve: give curves, a dual_chain, or both")
    vertices, offsets, m = _curve_arrays([] if curves is None else curves, multiplicities)
    options = _options(epsilon, lp_solver, linear_solver, reduced_residual, filter_nonbounding_loops, concurrency,
                       verbose, anchor_face, confidence, completed_homology_class)
    r = _swn._winding_numbers(V, F, vertices, offsets, m, _dual_pairs(dual_chain), _boolean(soup, "soup"), options)
    _warn(r["warnings"], 2)
    r["edges"].flags.writeable = False
    return _result(r, r["edges"])


def _cleaned(r):
    _warn(r["warnings"], 3)
    r["edges"].flags.writeable = False
    return CleanSelection(selected=r["selected"], bounding=r["bounding"], edges=r["edges"], report=r["report"])


def clean_face_selection(V, F, selection, *, epsilon=0.01, lp_solver=None, linear_solver=None, reduced_residual=False,
                         filter_nonbounding_loops=True, concurrency=True, verbose=False):
    """Turns a noisy selection of faces of the triangle mesh (V, F) into a clean region (the library's
    ``clean_face_selection()``, paper Sec. 5.5).

    ``selection``: a boolean mask of the m faces, or an integer array of the selected faces' indices (m integers
    all 0 or 1 are refused as an ambiguous mask). A face whose state (selected or not) differs from that of more
    than half of the faces around its vertices and of more than half of its neighbours across edges is noise, but
    for a tooth of the border (a spike, a notch or a corner of one face) with no noise face but teeth within two
    rings: an exact selection comes back unchanged. The border of the selection without the sides of noise faces
    is the curve, whose winding numbers close its gaps along short paths and filter out what remains of small
    pieces. The cleaned region is the set of faces whose label is above the reference label of their connected
    component: the label covering the most unselected faces (a component whose faces are all selected stays
    selected). A cluster of noise large enough that its faces see mostly their own state is kept. The settings
    are those of ``winding_numbers()``.
    Returns a ``CleanSelection``. Raises ``ValueError`` on a bad mesh, selection or setting, ``RuntimeError``
    when the solver fails.
    """
    m = len(F)
    s = np.asarray(selection)
    if s.dtype == bool:
        if s.shape != (m,):
            raise ValueError(f"selection: a boolean mask needs one value per face ({m}), not shape {s.shape}")
        mask = s
    elif s.dtype.kind in "iu" and s.ndim == 1:
        if m > 2 and s.size == m and np.isin(s, (0, 1)).all():
            raise ValueError(f"selection: {m} integers, all 0 or 1, look like a mask of the faces: give it as booleans "
                             "(selection.astype(bool)) or give face indices")
        if s.size and (s.min() < 0 or s.max() >= m):
            raise ValueError(f"selection: face index {s.min() if s.min() < 0 else s.max()} is out of range ({m} faces)")
        mask = np.zeros(m, bool)
        mask[s] = True
    else:
        raise TypeError(f"selection must be a boolean mask of the faces or an array of face indices, not {s.dtype} "
                        f"of shape {s.shape}")
    options = _options(epsilon, lp_solver, linear_solver, reduced_residual, filter_nonbounding_loops, concurrency, verbose)
    return _cleaned(_swn._clean_face_selection(V, F, mask.view(np.uint8), options))


def clean_edge_selection(V, F, selection, *, epsilon=0.01, lp_solver=None, linear_solver=None, reduced_residual=False,
                         filter_nonbounding_loops=True, concurrency=True, verbose=False):
    """Turns a noisy selection of unoriented edges of the triangle mesh (V, F), the border of a region with gaps
    and spurious pieces, into a clean region (the library's ``clean_edge_selection()``, paper Fig. 25).

    ``selection``: the selected edges as vertex pairs, an integer array of shape (k, 2) (either way round), or a
    boolean mask in the order of the mesh's ``edges`` (``Solver.edges``, the ``edges`` of a result). The
    selection is oriented (``orient_edge_selection()``: the pieces of one loop or open curve head to tail, each
    loop counter-clockwise around the centroid of its cluster; open curves ending near one border of the mesh
    form one cluster), its winding numbers close the gaps and filter out the spurious pieces, and the region is the set
    of faces whose label is above the smallest label of their connected component: the inside of the loops,
    whether it covers less or more than half of the surface. The settings are those of ``winding_numbers()``.
    Returns a ``CleanSelection``. Raises ``ValueError`` on a bad mesh, selection or setting, ``RuntimeError``
    when the solver fails.
    """
    s = np.asarray(selection)
    if s.dtype == bool and s.ndim == 1:
        pairs, mask = s.astype(np.int64).reshape(-1, 1), True
    elif s.size == 0 or (s.dtype.kind in "iu" and s.ndim == 2 and s.shape[1] == 2):
        pairs, mask = np.ascontiguousarray(s.reshape(-1, 2).astype(np.int64, copy=False)), False
    else:
        raise TypeError(f"selection must be edges as vertex pairs of shape (k, 2) or a boolean mask of the edges, "
                        f"not {s.dtype} of shape {s.shape}")
    options = _options(epsilon, lp_solver, linear_solver, reduced_residual, filter_nonbounding_loops, concurrency, verbose)
    return _cleaned(_swn._clean_edge_selection(V, F, pairs, mask, options))


def read_mesh(path):
    """Reads a triangle mesh file (OFF, OBJ, PLY or STL, by its extension) with the swn tool's reader.

    Returns ``(V, F)``: vertex ``i`` and face ``j`` of the file are ``V[i]`` and ``F[j]``, each face's
    vertices in the file's order. Unreferenced vertices are kept; they and exactly duplicated positions
    give a ``MeshWarning``. Raises ``InputError`` (``FILE:LINE: reason``) on a missing file or bad
    input (unparsable line, index out of range, non-triangle face, non-finite coordinate, a surface
    that is not an oriented 2-manifold).
    """
    V, F, messages = _swn._read_mesh(os.fspath(path))
    _warn(messages, 2)
    return V, F


def _curve_on_mesh(d):
    _warn(d["info"]["warnings"], 3)
    return CurveOnMesh(V=d["V"], F=d["F"], halfedges=d["halfedges"], multiplicities=d["multiplicities"],
                       info=d["info"], face_origin=d["face_origin"])


def read_curve(path, V, F, *, refine_short_pieces=True, minimum_piece_edges=8):
    """Reads a curve file as the swn tool does, on the mesh (V, F) (as returned by ``read_mesh()``).

    Formats: the authors' curve files (``v`` vertex points, ``e`` points on edges in the authors' edge
    numbering, ``l`` segments, ``#offset``), ``# swn polylines`` (0-based vertex polylines, one per line)
    and ``# swn halfedges`` (``h SRC DST [M]``). The curves are put on the edges of the mesh with the
    tool's conforming cut: points on edges become new vertices, and pieces of fewer than
    ``minimum_piece_edges`` edges that end inside the mesh are refined (``refine_short_pieces``). Returns a
    ``CurveOnMesh``: the mesh the curves live on (V and F unchanged when there was nothing to cut or
    refine) and the curves as halfedges with multiplicities, ready for ``winding_numbers()``. Raises
    ``InputError`` (``FILE:LINE: reason``) on a bad file, ``ValueError`` on a bad mesh.
    """
    return _curve_on_mesh(_swn._read_curve(os.fspath(path), V, F, bool(refine_short_pieces), int(minimum_piece_edges)))


def load(mesh_path, curve_path=None, *, refine_short_pieces=True, minimum_piece_edges=8):
    """Reads a mesh and its curves as the swn tool does: the ``l`` lines of an OBJ mesh and/or a curve file.

    Same as ``read_mesh()`` then ``read_curve()``, the OBJ's own polylines (1-based, ``#offset``
    honoured) included; returns a ``CurveOnMesh``. Raises ``InputError`` when there is no curve at all.
    """
    curve_path = None if curve_path is None else os.fspath(curve_path)
    return _curve_on_mesh(_swn._load(os.fspath(mesh_path), curve_path, bool(refine_short_pieces),
                                     int(minimum_piece_edges)))


def _cut_settings(projection_tolerance, refine_short_pieces, minimum_piece_edges):
    if projection_tolerance is not None:
        t = float(projection_tolerance)
        if not np.isfinite(t) or t <= 0:
            raise ValueError(f"projection_tolerance must be positive and finite, not {projection_tolerance!r}")
        projection_tolerance = t
    if isinstance(minimum_piece_edges, (bool, np.bool_)) or int(minimum_piece_edges) != minimum_piece_edges \
            or minimum_piece_edges < 1:
        raise ValueError(f"minimum_piece_edges must be a positive integer, not {minimum_piece_edges!r}")
    return projection_tolerance, _boolean(refine_short_pieces, "refine_short_pieces"), int(minimum_piece_edges)


def polylines_to_chain(V, F, polylines, *, projection_tolerance=None, refine_short_pieces=True, minimum_piece_edges=8):
    """Puts 3D polylines drawn off the triangle mesh (V, F) onto its surface (the library's ``polylines_to_chain()``).

    ``polylines``: a sequence of (k, 3) point arrays (a polyline whose last point equals its first is closed).
    Every point is projected onto the surface (points farther than ``projection_tolerance``, default the mean
    edge length, make gaps); consecutive points are joined by a straight walk through the faces; the mesh
    is cut so that the curves run along edges (``refine_short_pieces``, ``minimum_piece_edges`` as for
    ``read_curve()``). Returns a ``CurveOnMesh``: the cut mesh, the curves' halfedges and multiplicities,
    ``face_origin`` (the input face of every face) and ``info`` (``points``, ``points_off_surface``,
    ``failed_walks``, ``crossing_vertices``, ``curves``, ``pieces``, ``border_pieces``: the pieces that ran along
    the border of the mesh, dropped, the cut's counts, ``warnings``). Raises ``ValueError`` on a bad mesh or
    polyline and when no curve lands on the surface (saying so when it all ran along the border).
    """
    settings = _cut_settings(projection_tolerance, refine_short_pieces, minimum_piece_edges)
    return _curve_on_mesh(_swn._polylines_to_chain(V, F, polylines, *settings))


def stamp_polylines(V, F, drawing, *, direction=(0, 0, -1), frame=None, fill=0.8, projection_tolerance=None,
                    refine_short_pieces=True, minimum_piece_edges=8):
    """Stamps a 2D drawing onto the triangle mesh (V, F) (the library's ``stamp_polylines()``), then puts it on
    the edges as ``polylines_to_chain()`` does.

    ``drawing``: an SVG file (``str`` or path: paths with M/L/H/V/Z, polyline, polygon, line, as the tool's
    ``--stamp``) or a sequence of (k, 2) point arrays. ``frame``: ``(origin, x_axis, y_axis, direction)``,
    four 3-vectors: the drawing's point (x, y) is shot from ``origin + x x_axis + y y_axis`` along
    ``direction`` and lands where the ray first hits the surface from the front. Without a frame, the one
    that shows the drawing to a viewer looking along ``direction``, x to the right and y downwards (as in
    SVG), centred on the mesh and covering the fraction ``fill`` of its extent (``fit_stamp_frame()``); the
    frame used is ``info["frame"]``. Returns a ``CurveOnMesh`` with ``face_origin``.
    """
    settings = _cut_settings(projection_tolerance, refine_short_pieces, minimum_piece_edges)
    if isinstance(drawing, (str, os.PathLike)):
        drawing = os.fspath(drawing)
    if frame is not None:
        frame = np.asarray(frame, dtype=float)
        if frame.shape != (4, 3):
            raise ValueError(f"frame must be four 3-vectors (origin, x_axis, y_axis, direction), not of shape {frame.shape}")
        frame = [list(v) for v in frame]
    direction = np.asarray(direction, dtype=float)
    if direction.shape != (3,):
        raise ValueError(f"direction must be three numbers, not of shape {direction.shape}")
    return _curve_on_mesh(_swn._stamp_polylines(V, F, drawing, frame, list(direction), float(fill), *settings))
