#!/usr/bin/python3
"""Figures from a coldspray run's output folder.

`coldspray run CASE.yaml --out DIR` writes DIR/summary.json, DIR/history.csv,
DIR/snapshots.pvd, DIR/snapshots/step_XXXXXXXX.vtu and DIR/case.resolved.yaml.
This tool reads them and writes PNG figures:

  section DIR [DIR2 ...] --times 10ns,40ns,80ns --field eqps --out eqps.png
      cross-sections of the bodies coloured by a point field, one panel per run and time;
  history DIR [DIR2 ...] --columns cor,v_rest --body particle --out history.png
      history.csv columns against time, several runs overlaid;
  deposit DIR --out deposit.png
      a deposit's thickness map and section (coldspray deposit);
  material-test A.csv [B.csv ...] --johnson-cook A,B,n,C,m,T_m --out curves.png
      coldspray material-test curves beside the published Johnson-Cook formula;
  info DIR
      what a run folder holds: snapshot times, point fields, history columns.

Only the standard library, numpy and matplotlib (Debian's python3-numpy and
python3-matplotlib). Errors go to stderr with exit status 2, and no PNG is written.
See docs/plotting.md.
"""

import argparse
import csv
import math
import os
import re
import sys
import tempfile
import xml.etree.ElementTree as ET

import numpy as np
import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.patches  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402  (after the backend is chosen)
from matplotlib.collections import PolyCollection  # noqa: E402

EXIT_ERROR = 2
METRE_TO_UM = 1e6
SECOND_TO_NS = 1e9


class PlotError(Exception):
    """A user-facing error: the message names the file or argument at fault."""


# --------------------------------------------------------------------------------------
# Numbers with units
# --------------------------------------------------------------------------------------

TIME_UNITS = {"": 1.0, "s": 1.0, "ms": 1e-3, "us": 1e-6, "\u00b5s": 1e-6, "\u03bcs": 1e-6,
              "ns": 1e-9, "ps": 1e-12}
LENGTH_UNITS = {"": 1.0, "m": 1.0, "mm": 1e-3, "um": 1e-6, "\u00b5m": 1e-6, "\u03bcm": 1e-6,
                "nm": 1e-9}
_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S*)\s*$")


def parse_quantity(text, units, what):
    """Parses '80ns', '80 ns', '8e-8' (no unit: SI) into an SI float using `units`."""
    match = _QUANTITY.match(text)
    if not match or match.group(2) not in units:
        known = ", ".join(u for u in units if u)
        raise PlotError(f"{what}: cannot read '{text}' (a number with an optional unit: {known})")
    return float(match.group(1)) * units[match.group(2)]


def parse_time(text, what="--times"):
    return parse_quantity(text, TIME_UNITS, what)


def split_list(values):
    """Flattens repeated and comma-separated option values: ['a,b', 'c'] -> ['a', 'b', 'c']."""
    items = []
    for value in values or []:
        items.extend(part.strip() for part in value.split(",") if part.strip())
    return items


def parse_range(text, what):
    """'0:3' -> (0.0, 3.0); either side may be empty (None: automatic)."""
    low, sep, high = text.partition(":")
    if not sep:
        raise PlotError(f"{what}: '{text}' is not LOW:HIGH")
    try:
        bounds = tuple(float(v) if v.strip() else None for v in (low, high))
    except ValueError:
        raise PlotError(f"{what}: '{text}' is not LOW:HIGH with numbers") from None
    if None not in bounds and bounds[0] >= bounds[1]:
        raise PlotError(f"{what}: '{text}' needs LOW < HIGH")
    return bounds


# --------------------------------------------------------------------------------------
# case.resolved.yaml: a small reader for the block YAML that coldspray writes
# --------------------------------------------------------------------------------------

_YAML_KEY = re.compile(r"^([^\s:#'\"][^:#]*?)\s*:(?:\s+(.*))?$")


def _strip_comment(line):
    """Removes a trailing ' # comment' that is not inside a quoted scalar."""
    quote = None
    for i, char in enumerate(line):
        if quote:
            quote = None if char == quote else quote
        elif char in "'\"" and (i == 0 or line[i - 1] in " \t[{,"):  # not an apostrophe
            quote = char
        elif char == "#" and (i == 0 or line[i - 1].isspace()):
            return line[:i].rstrip()
    return line.rstrip()


def _yaml_lines(text):
    """(indent, content) for each line that holds something."""
    lines = []
    for raw in text.splitlines():
        content = _strip_comment(raw)
        if content.strip():
            lines.append([len(content) - len(content.lstrip(" ")), content.strip()])
    return lines


def _yaml_scalar(text):
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":
        return text[1:-1]
    return text  # numbers and flow collections ([0, 0, 1]) stay text


def _parse_yaml_node(lines, i, indent):
    if lines[i][1] == "-" or lines[i][1].startswith("- "):
        return _parse_yaml_sequence(lines, i, indent)
    return _parse_yaml_mapping(lines, i, indent)


def _parse_yaml_mapping(lines, i, indent):
    mapping = {}
    while i < len(lines) and lines[i][0] == indent:
        match = _YAML_KEY.match(lines[i][1])
        if not match:
            break
        key, value = match.group(1), match.group(2)
        i += 1
        nested = i < len(lines) and (lines[i][0] > indent or
                                     (lines[i][0] == indent and lines[i][1].startswith("-")))
        if value is None and nested:
            mapping[key], i = _parse_yaml_node(lines, i, lines[i][0])
        else:
            mapping[key] = _yaml_scalar(value or "")
    return mapping, i


def _parse_yaml_sequence(lines, i, indent):
    items = []
    while i < len(lines) and lines[i][0] == indent and lines[i][1].startswith("-"):
        rest = lines[i][1][1:].lstrip()
        if not rest:
            i += 1
            item, i = _parse_yaml_node(lines, i, lines[i][0]) if i < len(lines) else (None, i)
        elif _YAML_KEY.match(rest):
            # '- key: value' opens a mapping whose keys line up with 'key'.
            lines[i] = [indent + len(lines[i][1]) - len(rest), rest]
            item, i = _parse_yaml_mapping(lines, i, lines[i][0])
        else:
            item, i = _yaml_scalar(rest), i + 1
        items.append(item)
    return items, i


def parse_yaml(text):
    """Block mappings and sequences with scalar leaves (as text): what case.resolved.yaml uses."""
    lines = _yaml_lines(text)
    if not lines:
        return {}
    node, _ = _parse_yaml_node(lines, 0, lines[0][0])
    return node


class CaseInfo:
    """The few keys of case.resolved.yaml the figures need."""

    def __init__(self, path):
        self.path = path
        data = parse_yaml(read_text(path))
        if not isinstance(data, dict):
            raise PlotError(f"{path}: not a case file")
        solver = data.get("solver") or {}
        self.geometry = solver.get("geometry", "3d") if isinstance(solver, dict) else "3d"
        self.body_names, self.spacings = [], []
        for n, body in enumerate(data.get("bodies") or []):
            if not isinstance(body, dict) or "name" not in body or "spacing" not in body:
                raise PlotError(f"{path}: bodies[{n}] needs a name and a spacing")
            self.body_names.append(body["name"])
            self.spacings.append(parse_quantity(body["spacing"], LENGTH_UNITS,
                                                f"{path}: bodies[{n}].spacing"))
        if not self.body_names:
            raise PlotError(f"{path}: no bodies")

    @property
    def axisymmetric(self):
        return self.geometry == "axisymmetric"


# --------------------------------------------------------------------------------------
# Files of a run folder
# --------------------------------------------------------------------------------------

def read_text(path):
    try:
        with open(path, encoding="utf-8") as f:
            return f.read()
    except OSError as e:
        raise PlotError(f"{path}: cannot read ({e.strerror})") from None


def require_dir(path):
    if not os.path.isdir(path):
        raise PlotError(f"{path}: no such run folder")
    return path


_VTK_TYPES = {"Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4",
              "UInt32": "u4", "Int64": "i8", "UInt64": "u8", "Float32": "f4", "Float64": "f8"}


class VtuData:
    """A point cloud from a .vtu file: `points` (n x 3) and `arrays` (name -> n or n x k)."""

    def __init__(self, points, arrays):
        self.points = points
        self.arrays = arrays

    def __len__(self):
        return len(self.points)


def _vtu_split(raw, path):
    """Splits a VTU with raw appended data into (XML header root, start of the data)."""
    tag = re.search(rb"<AppendedData\b[^>]*>", raw)
    if not tag:
        raise PlotError(f"{path}: no <AppendedData> (only appended raw VTU files are read)")
    if b'encoding="raw"' not in tag.group(0):
        raise PlotError(f"{path}: appended data is not raw (only encoding=\"raw\" is read)")
    underscore = raw.find(b"_", tag.end())
    if underscore < 0:
        raise PlotError(f"{path}: appended data has no '_' marker")
    try:
        root = ET.fromstring(raw[:tag.start()] + b"</VTKFile>")
    except ET.ParseError as e:
        raise PlotError(f"{path}: bad XML header ({e})") from None
    return root, underscore + 1


def _vtu_array(raw, start, element, count, header, path):
    """Reads one appended DataArray of `count` tuples; returns a 1D or 2D numpy array."""
    name = element.get("Name", "Points")
    vtk_type, components = element.get("type"), int(element.get("NumberOfComponents", "1"))
    if element.get("format") != "appended" or vtk_type not in _VTK_TYPES:
        raise PlotError(f"{path}: array '{name}' is not an appended array of a known type")
    position = start + int(element.get("offset"))
    if position + header.itemsize > len(raw):
        raise PlotError(f"{path}: array '{name}' lies beyond the end of the file")
    nbytes = int(np.frombuffer(raw, header, 1, position)[0])
    dtype = np.dtype("<" + _VTK_TYPES[vtk_type])
    if nbytes != count * components * dtype.itemsize or position + header.itemsize + nbytes > len(raw):
        raise PlotError(f"{path}: array '{name}' has {nbytes} bytes, "
                        f"expected {count} x {components} {vtk_type}")
    values = np.frombuffer(raw, dtype, count * components, position + header.itemsize)
    return values.reshape(count, components) if components > 1 else values


def read_vtu(path):
    """Reads the points and every point-data array of an appended-raw VTU file."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
    except OSError as e:
        raise PlotError(f"{path}: cannot read ({e.strerror})") from None
    root, start = _vtu_split(raw, path)
    if root.get("byte_order", "LittleEndian") != "LittleEndian" or root.get("compressor"):
        raise PlotError(f"{path}: only little-endian uncompressed VTU files are read")
    header = np.dtype("<u8" if root.get("header_type", "UInt32") == "UInt64" else "<u4")
    points, arrays = [], {}
    for piece in root.iter("Piece"):
        count = int(piece.get("NumberOfPoints", "0"))
        element = piece.find("Points/DataArray")
        if element is None:
            raise PlotError(f"{path}: a piece has no <Points>")
        points.append(_vtu_array(raw, start, element, count, header, path))
        for element in piece.findall("PointData/DataArray"):
            values = _vtu_array(raw, start, element, count, header, path)
            arrays.setdefault(element.get("Name"), []).append(values)
    if not points:
        raise PlotError(f"{path}: no <Piece>")
    return VtuData(np.concatenate(points).reshape(-1, 3),
                   {name: np.concatenate(parts) for name, parts in arrays.items()})


def read_pvd(path):
    """[(time in s, absolute .vtu path)] from a ParaView collection, sorted by time."""
    try:
        root = ET.fromstring(read_text(path))
    except ET.ParseError as e:
        raise PlotError(f"{path}: bad XML ({e})") from None
    folder = os.path.dirname(os.path.abspath(path))
    entries = [(float(d.get("timestep", "nan")), os.path.join(folder, d.get("file", "")))
               for d in root.iter("DataSet")]
    if not entries:
        raise PlotError(f"{path}: lists no snapshots")
    return sorted(entries)


class History:
    """history.csv: column names and a float table (nan where a cell says nan or is empty)."""

    def __init__(self, path):
        self.path = path
        rows = list(csv.reader(read_text(path).splitlines()))
        if not rows or "time" not in rows[0]:
            raise PlotError(f"{path}: no header with a 'time' column")
        self.columns = [c.strip() for c in rows[0]]
        self.values = np.array([[_to_float(cell) for cell in row] for row in rows[1:]
                                if len(row) == len(self.columns)], dtype=float)
        if self.values.size == 0:
            raise PlotError(f"{path}: no rows")

    def column(self, name):
        return self.values[:, self.columns.index(name)]


def _to_float(cell):
    try:
        return float(cell)
    except ValueError:
        return math.nan


# --------------------------------------------------------------------------------------
# Writing a figure without leaving half a file
# --------------------------------------------------------------------------------------

def save_figure(fig, out, dpi):
    """Saves `fig` as PNG to a temporary file next to `out`, then renames it to `out`."""
    folder = os.path.dirname(os.path.abspath(out))
    if not os.path.isdir(folder):
        raise PlotError(f"--out {out}: folder {folder} does not exist")
    temporary = None
    try:
        handle, temporary = tempfile.mkstemp(prefix=".coldspray_plot-", suffix=".png", dir=folder)
        os.close(handle)
        # tight: the margins fit whatever the tick labels need, nothing is cut off
        fig.savefig(temporary, format="png", dpi=dpi, bbox_inches="tight", pad_inches=0.05)
        os.chmod(temporary, 0o666 & ~_umask())  # mkstemp makes it private; a figure is not
        os.replace(temporary, out)
    except OSError as e:
        raise PlotError(f"--out {out}: cannot write ({e.strerror or e})") from None
    finally:
        if temporary and os.path.exists(temporary):
            os.remove(temporary)
        plt.close(fig)


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


# --------------------------------------------------------------------------------------
# section: cross-sections coloured by a point field
# --------------------------------------------------------------------------------------

def pick_snapshots(entries, times, pvd_path):
    """For each requested time, the (time, file) of the nearest snapshot."""
    first, last = entries[0][0], entries[-1][0]
    slack = 0.01 * (last - first) if last > first else 1e-12
    chosen = []
    for text, t in times:
        if t < first - slack or t > last + slack:
            raise PlotError(f"--times {text}: outside the run's snapshots "
                            f"({first * SECOND_TO_NS:g} to {last * SECOND_TO_NS:g} ns, {pvd_path})")
        chosen.append(min(entries, key=lambda entry: abs(entry[0] - t)))
    return chosen


def field_values(data, field, path):
    """A point field by name; a vector field gives its magnitude, NAME.x/.y/.z a component."""
    name, _, component = field.partition(".")
    if name not in data.arrays:
        raise PlotError(f"--field {field}: no such point field in {path} "
                        f"(available: {', '.join(sorted(data.arrays))})")
    values = data.arrays[name].astype(float)
    if values.ndim == 1:
        if component:
            raise PlotError(f"--field {field}: '{name}' is a scalar field, it has no components")
        return values
    if not component:
        return np.linalg.norm(values, axis=1)
    axes = {"x": 0, "y": 1, "z": 2, "r": 0}
    if axes.get(component, 99) >= values.shape[1]:
        raise PlotError(f"--field {field}: component '{component}' is not one of x, y, z")
    return values[:, axes[component]]


def slab_mask(y, spacing):
    """3D runs: the points within 0.6 spacing of y = 0, or else of the middle of their y range."""
    mask = np.abs(y) < 0.6 * spacing
    if not mask.any() and len(y):
        middle = 0.5 * (y.min() + y.max())
        mask = np.abs(y - middle) < 0.6 * spacing
    return mask


class Section:
    """The points of one snapshot in the plot plane: horizontal h, vertical v (m), size, values."""

    def __init__(self, h, v, size, values):
        self.h, self.v, self.size, self.values = h, v, size, values


def make_section(data, case, body_ids, fields, path, reference=None):
    """Cuts the snapshot: selected bodies, the y ~ 0 slab in 3D, mirrored to -r if axisymmetric.

    With `reference` (the first snapshot, same points), the 3D slab is the points that were in it
    there: the same material section at every time, whatever the points' motion across y.
    Snapshots with the points' half widths (coarsened bodies' points stand for blocks of several
    spacings) cut and draw each point by its own domain."""
    if "body" not in data.arrays:
        raise PlotError(f"{path}: no 'body' point array")
    body = data.arrays["body"]
    spacing = np.array(case.spacings)[np.clip(body, 0, len(case.spacings) - 1)]
    half_width = data.arrays.get("half_width")
    keep = np.isin(body, body_ids)
    if not case.axisymmetric:
        if reference is not None and len(reference) != len(data):
            raise PlotError(f"{path}: --cut material needs the first snapshot's points "
                            f"({len(reference)}), this one has {len(data)}")
        cut = reference if reference is not None else data
        y = cut.points[:, 1]
        if half_width is not None and "half_width" in cut.arrays:
            # The points whose domain the plane y = 0 crosses (as slab_mask's 0.6 spacing).
            keep &= np.abs(y) < 1.2 * cut.arrays["half_width"][:, 1]
        else:
            for b in body_ids:  # each body's slab from its own spacing
                on_body = body == b
                keep[on_body] &= slab_mask(y[on_body], case.spacings[b])
    h, v = data.points[keep, 0], data.points[keep, 2]
    values = {f: field_values(data, f, path)[keep] for f in fields}
    size = spacing[keep] if half_width is None else 2.0 * half_width[keep, 0]
    if case.axisymmetric:  # the points are (r, z): draw the mirror image at -r too
        h = np.concatenate([h, -h])
        v, size = np.tile(v, 2), np.tile(size, 2)
        values = {f: np.tile(values[f], 2) for f in fields}
    return Section(h, v, size, values)


def squares(section):
    """One square per point, of the point's spacing, in micrometres: neighbours just touch."""
    half = 0.5 * section.size * METRE_TO_UM
    h, v = section.h * METRE_TO_UM, section.v * METRE_TO_UM
    corners = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    return np.stack([h, v], axis=1)[:, None, :] + half[:, None, None] * corners[None, :, :]


def plot_limits(sections, xlim, ylim):
    """The panels' common limits (um): the union of the sections unless given."""
    def span(coordinate):
        low = min(float(np.min(getattr(s, coordinate) - s.size)) for s in sections if len(s.h))
        high = max(float(np.max(getattr(s, coordinate) + s.size)) for s in sections if len(s.h))
        return low * METRE_TO_UM, high * METRE_TO_UM
    if not any(len(s.h) for s in sections):
        raise PlotError("section: no points to draw (check --bodies)")
    return (xlim or span("h")), (ylim or span("v"))


def colour_ranges(fields, sections, ranges):
    """Per field (vmin, vmax): from --range where given, else the drawn values' extremes."""
    result = {}
    for field in fields:
        values = np.concatenate([s.values[field] for s in sections])
        values = values[np.isfinite(values)]
        low, high = ranges.get(field, (None, None))
        if low is None:
            low = float(values.min()) if values.size else 0.0
        if high is None:
            high = float(values.max()) if values.size else 1.0
        if high <= low:
            high = low + (abs(low) * 1e-6 or 1.0)
        result[field] = (low, high)
    return result


def match_ranges(fields, texts):
    """--range [FIELD=]LOW:HIGH: with a field name, for that field; without, by position."""
    ranges = {}
    for n, text in enumerate(texts or []):
        field, sep, bounds = text.rpartition("=")
        if not sep:
            if n >= len(fields):
                raise PlotError(f"--range {text}: more ranges than fields")
            field = fields[n]
        elif field not in fields:
            raise PlotError(f"--range {text}: '{field}' is not one of the --field values")
        ranges[field] = parse_range(bounds, f"--range {text}")
    return ranges


FIELD_LABELS = {"eqps": "effective plastic strain", "temperature": "temperature (K)",
                "pressure": "pressure (Pa)", "von_mises": "von Mises stress (Pa)",
                "density": "density (kg/m$^3$)", "velocity": "speed (m/s)"}


def field_label(field):
    name, _, component = field.partition(".")
    if component and name == "velocity":
        return f"velocity {component} (m/s)"
    return FIELD_LABELS.get(field, field)


def draw_panel(ax, section, field, limits, norm, cmap):
    collection = PolyCollection(squares(section), array=section.values[field], cmap=cmap,
                                norm=norm, edgecolors="face", linewidths=0.15, antialiaseds=False)
    ax.add_collection(collection)
    ax.set_xlim(*limits[0])
    ax.set_ylim(*limits[1])
    ax.set_aspect("equal")
    return collection


# The section figure's layout in inches: panels of fixed size, so equal-aspect panels fill
# their slots exactly (a layout engine would leave gaps around them).
LAYOUT = {"left": 0.7, "gap": 0.3, "top": 0.35, "bottom": 0.55, "bar_gap": 0.15,
          "bar": 0.14, "bar_label": 0.9}


def panel_grid(fig_rows, fig_columns, width, height):
    """A figure with rows x columns axes of width x height inches, and one colour-bar axes
    per row; returns (figure, axes[row][column], bar axes[row])."""
    L = LAYOUT
    fig_width = (L["left"] + fig_columns * width + (fig_columns - 1) * L["gap"] + L["bar_gap"]
                 + L["bar"] + L["bar_label"])
    row_height = L["top"] + height + L["bottom"]
    fig = plt.figure(figsize=(fig_width, fig_rows * row_height))
    fig_height = fig_rows * row_height

    def rect(x, y, w, h):  # inches from the bottom left -> figure fractions
        return [x / fig_width, y / fig_height, w / fig_width, h / fig_height]

    axes, bars = [], []
    for row in range(fig_rows):
        y = (fig_rows - 1 - row) * row_height + L["bottom"]
        x = [L["left"] + c * (width + L["gap"]) for c in range(fig_columns)]
        axes.append([fig.add_axes(rect(x[c], y, width, height)) for c in range(fig_columns)])
        bar_x = x[-1] + width + L["bar_gap"]
        bars.append(fig.add_axes(rect(bar_x, y + 0.05 * height, L["bar"], 0.9 * height)))
    return fig, axes, bars


def section_figure(panels, fields, options):
    """Rows = fields, columns = panels (one per run and time); one colour bar per row.
    Each panel is (case, title, section)."""
    sections = [section for _, _, section in panels]
    limits = plot_limits(sections, options.xlim, options.ylim)
    ranges = colour_ranges(fields, sections, options.ranges)
    aspect = (limits[1][1] - limits[1][0]) / (limits[0][1] - limits[0][0])
    width = options.panel_width
    fig, axes, bars = panel_grid(len(fields), len(panels), width, width * aspect)
    for row, field in enumerate(fields):
        norm = matplotlib.colors.Normalize(*ranges[field])
        for column, (case, title, section) in enumerate(panels):
            ax = axes[row][column]
            mappable = draw_panel(ax, section, field, limits, norm, options.cmap)
            ax.set_title(title)
            ax.set_xlabel(f"{'r' if case.axisymmetric else 'x'} (\u00b5m)")
            if column == 0:
                ax.set_ylabel("z (\u00b5m)")
            else:
                ax.tick_params(labelleft=False)
        fig.colorbar(mappable, cax=bars[row], label=field_label(field))
    return fig


def body_ids_for(case, names):
    if not names:
        return list(range(len(case.body_names)))
    unknown = [n for n in names if n not in case.body_names]
    if unknown:
        raise PlotError(f"--bodies {','.join(unknown)}: not in {case.path} "
                        f"(bodies: {', '.join(case.body_names)})")
    return [case.body_names.index(n) for n in names]


def run_sections(folder, times, fields, options):
    """The run's case and its sections at the given times."""
    folder = require_dir(folder)
    case = CaseInfo(os.path.join(folder, "case.resolved.yaml"))
    body_ids = body_ids_for(case, split_list(options.bodies))
    pvd = os.path.join(folder, "snapshots.pvd")
    entries = read_pvd(pvd)
    snapshots = pick_snapshots(entries, times, pvd)
    reference = read_vtu(entries[0][1]) if options.cut == "material" else None
    sections = []
    for time, path in snapshots:
        data = read_vtu(path)
        sections.append((time, make_section(data, case, body_ids, fields, path, reference)))
    return case, sections


def command_section(options):
    fields = split_list(options.field) or ["eqps"]
    options.ranges = match_ranges(fields, options.range)
    options.xlim = parse_range(options.xlim, "--xlim") if options.xlim else None
    options.ylim = parse_range(options.ylim, "--ylim") if options.ylim else None
    if any(None in lim for lim in (options.xlim, options.ylim) if lim):
        raise PlotError("--xlim/--ylim: give both ends")
    times = [(text, parse_time(text)) for text in split_list(options.times)]
    if not times:
        raise PlotError("--times: give at least one time")
    if options.cmap not in matplotlib.colormaps:
        raise PlotError(f"--cmap {options.cmap}: not a matplotlib colour map")
    labels = run_labels(options.dir, options.labels)
    panels = []
    for folder, label in zip(options.dir, labels):
        case, sections = run_sections(folder, times, fields, options)
        for time, section in sections:
            title = f"t = {time * SECOND_TO_NS:.4g} ns"
            panels.append((case, f"{label}, {title}" if len(options.dir) > 1 else title, section))
    fig = section_figure(panels, fields, options)
    save_figure(fig, options.out, options.dpi)


# --------------------------------------------------------------------------------------
# history: history.csv columns against time
# --------------------------------------------------------------------------------------

QUANTITY_UNITS = {"kinetic": "J", "elastic": "J", "plastic_work": "J", "viscous": "J",
                  "absorbed": "J", "contact": "J", "departed": "J", "total": "J", "vx": "m/s",
                  "vy": "m/s", "vz": "m/s", "contact_fx": "N", "contact_fy": "N", "contact_fz": "N",
                  "v_rest": "m/s", "plastic_energy_density": "J/m$^3$", "max_temperature": "K",
                  "pbcp": "%", "departed_mass": "kg"}


def resolve_column(history, column, body):
    """BODY.COLUMN when --body is given and the history has it, else COLUMN as written."""
    candidates = ([f"{body}.{column}"] if body else []) + [column]
    for name in candidates:
        if name in history.columns:
            return name
    raise PlotError(f"--columns {column}: no column {' or '.join(candidates)} in {history.path} "
                    f"(available: {', '.join(history.columns)})")


def run_labels(dirs, labels_text):
    labels = split_list([labels_text]) if labels_text else []
    if labels and len(labels) != len(dirs):
        raise PlotError(f"--labels: {len(labels)} labels for {len(dirs)} run folders")
    return labels or [os.path.basename(os.path.normpath(d)) or d for d in dirs]


def history_figure(histories, labels, columns, body, panel_width):
    fig, axes = plt.subplots(len(columns), 1, squeeze=False, sharex=True, layout="constrained",
                             figsize=(panel_width, 0.5 + 2.2 * len(columns)))
    for ax, column in zip(axes[:, 0], columns):
        for history, label in zip(histories, labels):
            name = resolve_column(history, column, body)
            ax.plot(history.column("time") * SECOND_TO_NS, history.column(name), label=label)
        unit = QUANTITY_UNITS.get(column.rpartition(".")[2])
        label = resolve_column(histories[0], column, body)
        ax.set_ylabel(f"{label} ({unit})" if unit else label)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time (ns)")
    if len(histories) > 1:
        axes[0, 0].legend()
    return fig


def command_history(options):
    columns = split_list(options.columns)
    if not columns:
        raise PlotError("--columns: give at least one column")
    labels = run_labels(options.dirs, options.labels)
    histories = [History(os.path.join(require_dir(d), "history.csv")) for d in options.dirs]
    for history in histories:  # every column must exist before anything is drawn
        for column in columns:
            resolve_column(history, column, options.body)
    fig = history_figure(histories, labels, columns, options.body, options.panel_width)
    save_figure(fig, options.out, options.dpi)


# --------------------------------------------------------------------------------------
# info: what a run folder holds
# --------------------------------------------------------------------------------------

def command_info(options):
    folder = require_dir(options.dir)
    case = CaseInfo(os.path.join(folder, "case.resolved.yaml"))
    print(f"geometry: {case.geometry}")
    for name, spacing in zip(case.body_names, case.spacings):
        print(f"body {name}: spacing {spacing * METRE_TO_UM:g} um")
    pvd = os.path.join(folder, "snapshots.pvd")
    if os.path.exists(pvd):
        entries = read_pvd(pvd)
        print("snapshots (ns): " + ", ".join(f"{t * SECOND_TO_NS:.4g}" for t, _ in entries))
        data = read_vtu(entries[0][1])
        print("point fields: " + ", ".join(
            f"{n}[{a.shape[1]}]" if a.ndim > 1 else n for n, a in data.arrays.items()))
    history = os.path.join(folder, "history.csv")
    if os.path.exists(history):
        print("history columns: " + ", ".join(History(history).columns))



# --------------------------------------------------------------------------------------
# Studies: vcrit, pbcp-velocity, calibration (docs/studies.md)
# --------------------------------------------------------------------------------------

# Thesis Table 5.4: predicted critical velocity per particle size (um -> m/s).
THESIS_TABLE_54 = [(14, 824), (18, 809), (22, 791), (26, 776), (30, 761)]
# The experimental critical velocities the thesis calibrates on (§5.1.1), +-2 %.
EXPERIMENTS = [(14, 810), (30, 770)]


def read_csv_rows(path):
    if not os.path.exists(path):
        raise PlotError(f"{path}: no such file")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise PlotError(f"{path}: no rows")
    return rows


def read_json(path):
    import json
    try:
        with open(path) as f:
            return json.load(f)
    except OSError as e:
        raise PlotError(f"{path}: cannot read ({e.strerror})") from None
    except ValueError as e:
        raise PlotError(f"{path}: not JSON ({e})") from None


def command_vcrit(options):
    folder = require_dir(options.dir)
    rows = read_csv_rows(os.path.join(folder, "vcrit.csv"))
    d = np.array([_to_float(r["diameter_um"]) for r in rows])
    v = np.array([_to_float(r["vcrit_ms"]) for r in rows])
    lower = np.array([_to_float(r["lower_ms"]) for r in rows])
    fig, ax = plt.subplots(layout="constrained", figsize=(options.panel_width, 4.0))
    found = ~np.isnan(v)
    ax.errorbar(d[found], v[found], yerr=[v[found] - lower[found], 0 * v[found]],
                fmt="o", color="C0", capsize=3, label="coldspray (bracket below)")
    fit_path = os.path.join(folder, "vcrit_fit.json")
    span = np.array([min(d.min(), 14.0), max(d.max(), 30.0)])
    if os.path.exists(fit_path):
        fit = read_json(fit_path)
        ax.plot(span, fit["a"] + fit["b"] * span, "-", color="C0",
                label=f"fit: {fit['a']:.4g} + {fit['b']:.3g} d m/s")
    if not options.no_thesis:
        t = np.array(THESIS_TABLE_54, dtype=float)
        ax.plot(t[:, 0], t[:, 1], "s--", color="C1", label="thesis Table 5.4")
    if not options.no_experiments:
        e = np.array(EXPERIMENTS, dtype=float)
        ax.errorbar(e[:, 0], e[:, 1], yerr=0.02 * e[:, 1], fmt="k^", capsize=3,
                    label="experiment (±2 %)")
    ax.set_xlabel("particle diameter (um)")
    ax.set_ylabel("critical velocity (m/s)")
    ax.grid(True, alpha=0.3)
    ax.legend()
    save_figure(fig, options.out, options.dpi)


def command_pbcp_velocity(options):
    folder = require_dir(options.dir)
    rows = [r for r in read_csv_rows(os.path.join(folder, "vcrit_runs.csv")) if r["status"] == "ok"]
    if not rows:
        raise PlotError(f"{folder}/vcrit_runs.csv: no finished run")
    sizes = sorted({_to_float(r["diameter_um"]) for r in rows})
    fig, axes = plt.subplots(2, 1, sharex=True, layout="constrained",
                             figsize=(options.panel_width, 6.0))
    for k, size in enumerate(sizes):
        mine = sorted((_to_float(r["velocity_ms"]), r) for r in rows
                      if _to_float(r["diameter_um"]) == size)
        speed = [m[0] for m in mine]
        axes[0].plot(speed, [_to_float(m[1]["pbcp"]) for m in mine], "o-", color=f"C{k}",
                     label=f"{size:g} um")
        axes[1].plot(speed, [_to_float(m[1]["v_rest"]) for m in mine], "o-", color=f"C{k}")
    axes[0].axhline(options.pbcp_tolerance, color="k", ls="--", lw=1)
    for sign in (-1, 1):
        axes[1].axhline(sign * options.rest_tolerance, color="k", ls="--", lw=1)
    axes[0].set_ylabel("PBCP (%)")
    axes[1].set_ylabel("v_rest (m/s)")
    axes[1].set_xlabel("impact velocity (m/s)")
    for ax in axes:
        ax.grid(True, alpha=0.3)
    axes[0].legend(title="particle")
    save_figure(fig, options.out, options.dpi)


def command_sweep(options):
    """A sweep's result column against its varied key, one line per sweep folder (e.g. per
    impact speed: the PD paper's Fig 7 is particle.cor against contact.peridynamics.beta), or
    with --by one line per value of another varied key of the same folders."""
    labels = run_labels(options.dirs, options.labels) if not options.by else None
    fig, ax = plt.subplots(layout="constrained", figsize=(options.panel_width, 4.0))
    lines = []  # (label, [(x, y)])
    for k, folder in enumerate(options.dirs):
        rows = read_csv_rows(os.path.join(require_dir(folder), "sweep.csv"))
        for column in (options.x, options.y) + ((options.by,) if options.by else ()):
            if column not in rows[0]:
                raise PlotError(f"{folder}/sweep.csv: no column '{column}' "
                                f"(columns: {', '.join(rows[0])})")
        done = [r for r in rows if r["status"] == "ok"]
        if not done:
            raise PlotError(f"{folder}/sweep.csv: no finished case")
        groups = {}
        for r in done:
            groups.setdefault(r[options.by] if options.by else labels[k], []).append(
                (_to_float(r[options.x]), _to_float(r[options.y])))
        lines += [(f"{options.by} = {g}" if options.by else g, sorted(points))
                  for g, points in groups.items()]
    for k, (label, points) in enumerate(lines):
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", color=f"C{k}",
                label=label)
    ax.set_xlabel(options.x)
    ax.set_ylabel(options.y)
    ax.grid(True, alpha=0.3)
    ax.legend()
    save_figure(fig, options.out, options.dpi)


def command_bulk_fracture(options):
    """The PD paper's Fig 1: the bulk-fracture test's force-stretch curve and eq 24 fitted to it
    (coldspray bulk-fracture)."""
    folder = require_dir(options.dir)
    fit = read_json(os.path.join(folder, "fit.json"))
    rows = read_csv_rows(os.path.join(folder, "bulk_fracture.csv"))
    stretch = np.array([_to_float(r["stretch"]) for r in rows])
    scale = fit["micromodulus"] * fit["critical_stretch"]  # c s_c: the bulk bond's peak
    fig, ax = plt.subplots(layout="constrained", figsize=(options.panel_width, 3.8))
    for column, style, label in (("bulk_force_density", "-", "bulk (critical stretch)"),
                                 ("fitted_force_density", "--", "exponential (eq 24)")):
        ax.plot(stretch / fit["critical_stretch"],
                [_to_float(r[column]) / scale for r in rows], style, label=label)
    ax.set_xlabel("stretch / critical stretch $s_c$")
    ax.set_ylabel("force density / $c\\,s_c$")
    ax.set_title(f"{fit['material']}: $s_c$ = {fit['critical_stretch']:.4g}, "
                 f"$s_y$ = {fit['yield_stretch']:.4g}, m = {fit['softening']:.4g}")
    ax.grid(True, alpha=0.3)
    ax.legend()
    save_figure(fig, options.out, options.dpi)


def parse_johnson_cook(text):
    """--johnson-cook A,B,n,C,m,T_m[,T_ref,rate0]: A and B in MPa, T_m and T_ref in K, rate0 in
    1/s (defaults 298 K and 1 1/s). Returns (A Pa, B Pa, n, C, m, T_m, T_ref, rate0)."""
    parts = split_list([text])
    try:
        values = [float(p) for p in parts]
    except ValueError:
        raise PlotError(f"--johnson-cook {text}: not numbers") from None
    if len(values) not in (6, 8):
        raise PlotError(f"--johnson-cook {text}: give A,B,n,C,m,T_m or A,B,n,C,m,T_m,T_ref,rate0")
    if len(values) == 6:
        values += [298.0, 1.0]
    a, b, n, c, m, melt, t_ref, rate0 = values
    if not (melt > t_ref and rate0 > 0):
        raise PlotError(f"--johnson-cook {text}: needs T_m > T_ref and rate0 > 0")
    return (a * 1e6, b * 1e6, n, c, m, melt, t_ref, rate0)


def johnson_cook_stress(constants, eqps, rate, temperature):
    """Johnson & Cook 1983: (A + B eqps^n)(1 + C ln rate*)(1 - T*^m), with rate* = rate/rate0
    floored at 1 and T* = (T - T_ref)/(T_m - T_ref) clamped to [0, 1], as docs/materials.md."""
    a, b, n, c, m, melt, t_ref, rate0 = constants
    t_star = min(max((temperature - t_ref) / (melt - t_ref), 0.0), 1.0)
    return ((a + b * np.power(eqps, n)) * (1.0 + c * math.log(max(rate / rate0, 1.0)))
            * (1.0 - t_star ** m))


def command_material_test(options):
    """`coldspray material-test` curves (von Mises stress against plastic strain), and with
    --johnson-cook the published Johnson-Cook formula at each curve's plastic strain rate and
    initial temperature beside them."""
    labels = run_labels(options.csv, options.labels)
    constants = parse_johnson_cook(options.johnson_cook) if options.johnson_cook else None
    fig, ax = plt.subplots(layout="constrained", figsize=(options.panel_width, 4.0))
    for path, label in zip(options.csv, labels):
        rows = read_csv_rows(path)
        try:
            eqps = np.array([_to_float(r["eqps"]) for r in rows])
            stress = np.array([abs(_to_float(r["von_mises"])) for r in rows])
            rate = np.array([_to_float(r["eqps_rate"]) for r in rows])
            temperature = _to_float(rows[0]["temperature"])
        except KeyError as e:
            raise PlotError(f"{path}: no column {e} (not a material-test CSV)") from None
        line, = ax.plot(eqps, stress / 1e6, "-", label=f"{label}: coldspray material-test")
        flowing = eqps > 0
        if constants is None or not flowing.any():
            continue
        plastic_rate = float(np.median(rate[flowing]))
        grid = np.linspace(0.0, float(eqps.max()), 200)
        ax.plot(grid, johnson_cook_stress(constants, grid, plastic_rate, temperature) / 1e6, ":",
                color=line.get_color(), linewidth=2.5,
                label=f"{label}: published JC formula"
                      + (f" ({options.source})" if options.source else ""))
    ax.set_xlabel("equivalent plastic strain")
    ax.set_ylabel("von Mises stress (MPa)")
    if options.title:
        ax.set_title(options.title)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    save_figure(fig, options.out, options.dpi)


def command_pull_off(options):
    """The PD paper's Fig 11(b): force across the interface against the grip's displacement,
    one line per pull-off folder (coldspray pull-off), its peak marked."""
    folders = [require_dir(d) for d in options.dirs]
    labels = options.labels.split(",") if options.labels else [os.path.basename(
        os.path.normpath(d)) for d in folders]
    if len(labels) != len(folders):
        raise PlotError(f"--labels has {len(labels)} labels for {len(folders)} folders")
    fig, ax = plt.subplots(layout="constrained", figsize=(options.panel_width, 3.8))
    for k, folder in enumerate(folders):
        summary = read_json(os.path.join(folder, "summary.json"))
        rows = read_csv_rows(os.path.join(folder, "pull_off.csv"))
        ax.plot([_to_float(r["displacement"]) * 1e6 for r in rows],
                [_to_float(r["force"]) for r in rows], "-", color=f"C{k}",
                label=f"{labels[k]}: peak {summary['peak_force']:.3g} N, "
                      f"{summary['strength_projected'] * 1e-6:.3g} MPa (projected)")
        ax.plot(summary["peak_displacement"] * 1e6, summary["peak_force"], "o", color=f"C{k}")
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel("grip displacement (um)")
    ax.set_ylabel("force holding the splat (N)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    save_figure(fig, options.out, options.dpi)


def _speed(text):
    """The impact speed of a varied velocity such as "[0,0,-800 m/s]": its last number's size."""
    numbers = re.findall(r"[-+]?[0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?", text)
    if not numbers:
        raise PlotError(f"no number in the velocity '{text}'")
    return abs(float(numbers[-1]))


def command_bond_strength(options):
    """Bond strength against impact speed from a `coldspray sweep --pull-off` over the particle's
    velocity (over the bonded and the projected area), and the radial profile of one splat's bond
    strength (its pull-off's interface.csv: each bonded point's strength at the start)."""
    folder = require_dir(options.dir)
    rows = read_csv_rows(os.path.join(folder, "sweep.csv"))
    key = options.key
    for column in (key, "pull_off.strength_bonded", "pull_off.strength_projected"):
        if column not in rows[0]:
            raise PlotError(f"{folder}/sweep.csv: no column '{column}' (a sweep over {key} "
                            "with --pull-off makes them)")
    done = sorted(((_speed(r[key]), r) for r in rows if r["status"] == "ok"),
                  key=lambda item: item[0])
    if not done:
        raise PlotError(f"{folder}/sweep.csv: no finished case")
    profile = options.profile or max(
        done, key=lambda item: _to_float(item[1]["pull_off.strength_projected"]))[1]["case"]
    fig, (left, right) = plt.subplots(1, 2, layout="constrained",
                                      figsize=(2 * options.panel_width, 3.8))
    speeds = [v for v, _ in done]
    for column, label in (("pull_off.strength_bonded", "over the bonded area"),
                          ("pull_off.strength_projected", "over the projected area")):
        left.plot(speeds, [_to_float(r[column]) * 1e-6 for _, r in done], "o-", label=label)
    left.set_xlabel("impact speed (m/s)")
    left.set_ylabel("bond strength (MPa)")
    left.grid(True, alpha=0.3)
    left.legend(fontsize="small")
    points = read_csv_rows(os.path.join(require_dir(os.path.join(folder, profile)), "pull-off",
                                        "interface.csv"))
    right.scatter([_to_float(p["radius"]) * 1e6 for p in points],
                  [_to_float(p["strength"]) * 1e-6 for p in points],
                  c=[min(_to_float(p["bond"]), 1.0) for p in points], cmap="viridis", vmin=0,
                  vmax=1, s=12)
    right.set_xlabel("radius from the splat's axis (um)")
    right.set_ylabel("strength of the bonded point (MPa)")
    speed = dict((r["case"], v) for v, r in done).get(profile)
    right.set_title(f"{profile}" + (f", {speed:g} m/s" if speed is not None else "") +
                    ": colour min(D_bond, 1)", fontsize="small")
    right.grid(True, alpha=0.3)
    save_figure(fig, options.out, options.dpi)


VERDICT_COLOURS = {"bonded": "tab:green", "rebounded": "tab:red", "undecided": "tab:orange",
                   "none": "tab:gray"}


def command_deposit(options):
    """`coldspray deposit`'s picture: the deposit's thickness over the patch with each particle's
    footprint at its start (edge colour: its verdict), and an eqps section of the last snapshot
    through the plane y = --y."""
    folder = require_dir(options.dir)
    deposit = read_json(os.path.join(folder, "deposit.json"))
    case = CaseInfo(os.path.join(folder, "case.resolved.yaml"))
    entries = read_pvd(os.path.join(folder, "snapshots.pvd"))
    time, path = entries[-1]
    data = read_vtu(path)
    y0 = parse_quantity(options.y, LENGTH_UNITS, "--y")
    data.points = data.points - np.array([0.0, y0, 0.0])
    section = make_section(data, case, list(range(len(case.body_names))), ["eqps"], path)
    patch = np.array(deposit["patch"]) * METRE_TO_UM
    tmap = deposit["thickness_map"]
    thickness = np.array(tmap["values"]).reshape(tmap["columns_y"], tmap["columns_x"])
    fig, (top, side) = plt.subplots(1, 2, layout="constrained",
                                    figsize=(2 * options.panel_width, options.panel_width * 0.8),
                                    width_ratios=[1, 1.6])
    extent = [-patch[0] / 2, patch[0] / 2, -patch[1] / 2, patch[1] / 2]
    image = top.imshow(thickness * METRE_TO_UM, origin="lower", extent=extent, cmap="viridis")
    fig.colorbar(image, ax=top, label="deposit top above the substrate's surface (um)",
                 shrink=0.8)
    for particle in deposit["particles"]:
        x, y = (c * METRE_TO_UM for c in particle["centre"][:2])
        colour = VERDICT_COLOURS.get(particle["verdict"], "tab:gray")
        top.add_patch(matplotlib.patches.Circle((x, y), 0.5 * particle["diameter"] * METRE_TO_UM,
                                                fill=False, edgecolor=colour, lw=1.2))
        top.annotate(particle["name"], (x, y), ha="center", va="center", fontsize="x-small",
                     color=colour)
    top.axhline(y0 * METRE_TO_UM, color="w", lw=0.6, ls="--")
    top.set_xlim(extent[0], extent[1])
    top.set_ylim(extent[2], extent[3])
    top.set_xlabel("x (um)")
    top.set_ylabel("y (um)")
    top.set_title(f"DE {100 * deposit['deposition_efficiency']:.3g} %, porosity "
                  f"{100 * deposit['porosity']:.3g} %, mean thickness "
                  f"{deposit['mean_thickness'] * METRE_TO_UM:.3g} um", fontsize="small")
    limits = plot_limits([section], None, None)
    norm = matplotlib.colors.Normalize(0.0, float(np.max(section.values["eqps"], initial=1.0)))
    mappable = draw_panel(side, section, "eqps", limits, norm, "viridis")
    fig.colorbar(mappable, ax=side, label=field_label("eqps"), shrink=0.8)
    side.set_xlabel("x (um)")
    side.set_ylabel("z (um)")
    side.set_title(f"section y = {y0 * METRE_TO_UM:g} um at t = {time * SECOND_TO_NS:.4g} ns",
                   fontsize="small")
    save_figure(fig, options.out, options.dpi)


PARAMETER_LABELS = {"critical_energy": ("$G_c$ (J/m$^2$)", 1.0),
                    "critical_energy_rate": (r"$\dot G_c$ (J/m$^2$/us)", 1e-6),
                    "critical_strain": (r"$\epsilon_c$", 1.0),
                    "critical_strain_rate": (r"$\dot\epsilon_c$ (1/s)", 1.0)}


def plot_verdicts(ax, rows):
    """A size's runs classified by their verdicts (docs/bonding.md): margin against PBCP."""
    for outcome, colour, label in (("bonded", "C2", "bonded"), ("rebounded", "C3", "rebounded"),
                                   ("undecided", "0.6", "undecided (left out)")):
        pick = [r for r in rows if r["outcome"] == outcome]
        if pick:
            ax.plot([_to_float(r["pbcp"]) for r in pick], [_to_float(r["margin"]) for r in pick],
                    "o", color=colour, label=label, ms=4)
    ax.axhline(0.0, color="k", lw=1)
    ax.set_yscale("symlog", linthresh=1.0)
    ax.margins(0.08)
    ax.set_xlabel("PBCP (%)")
    ax.set_ylabel("margin (m/s): threshold - separation speed")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")


def command_calibration(options):
    folder = require_dir(options.dir)
    result = read_json(os.path.join(folder, "calibration.json"))
    rows = read_csv_rows(os.path.join(folder, "runs.csv"))
    keys = [result["parameters"]["x1"]["key"], result["parameters"]["x2"]["key"]]
    grids = result["grids"]
    sizes = grids[0]["sizes"]
    fig, axes = plt.subplots(1, len(sizes) + 1, layout="constrained", squeeze=False,
                             figsize=(options.panel_width * (len(sizes) + 1), 3.8))
    axes = axes[0]
    for ax, size in zip(axes, sizes):  # Fig 5.3a/b: restitution vs PBCP or ABP
        rule = size["classify"]
        if rule["by"] == "verdict":
            plot_verdicts(ax, [r for r in rows if r["size"] == size["size"] and r["status"] == "ok"])
            ax.set_title(f"{size['diameter_um']:g} um at {size['velocity_ms']:g} m/s")
            continue
        measure = "pbcp" if rule["by"] == "cor-pbcp" else "abp"
        mine = [r for r in rows if r["size"] == size["size"] and r["y"] != ""]
        for y, colour, label in (("1", "C2", "bonded"), ("0", "C3", "not bonded")):
            pick = [r for r in mine if r["y"] == y]
            ax.plot([_to_float(r[measure]) for r in pick], [_to_float(r["cor"]) for r in pick],
                    "o", color=colour, label=label, ms=4)
        ax.axhline(rule["cor_max"], color="k", lw=1)
        ax.axvline(rule[measure + "_min"], color="k", lw=1)
        ax.set_xlabel("PBCP (%)" if measure == "pbcp" else "average bond parameter")
        ax.set_ylabel("restitution ratio")
        ax.set_title(f"{size['diameter_um']:g} um at {size['velocity_ms']:g} m/s")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
    ax = axes[-1]  # Fig 5.3c / 5.1 (one grid) or Fig 5.7 (several): boundaries and crossing
    styles = ["-", "--", ":", "-."]
    (xlabel, xscale), (ylabel, yscale) = (PARAMETER_LABELS.get(k, (k, 1.0)) for k in keys)
    for g, grid in enumerate(grids):
        for s, size in enumerate(grid["sizes"]):
            if not size.get("boundary_csv"):
                continue
            b = read_csv_rows(os.path.join(folder, size["boundary_csv"]))
            for c, curve in enumerate(sorted({r["curve"] for r in b})):
                pts = np.array([[_to_float(r["x1"]), _to_float(r["x2"])] for r in b
                                if r["curve"] == curve])
                ax.plot(pts[:, 0] * xscale, pts[:, 1] * yscale, styles[g % 4], color=f"C{s}",
                        label=(f"{size['size']}" + (f", {grid['grid']}" if len(grids) > 1 else ""))
                        if c == 0 else None)
        if grid.get("calibrated"):
            p = grid["calibrated"]
            marker = "*PXD"[g % 4]  # one per grid, so overlaid grids' points stay apart
            ax.plot(p[keys[0]] * xscale, p[keys[1]] * yscale, "k" + marker,
                    ms=12 if marker == "*" else 8,
                    label=f"calibrated ({grid['grid']})" if len(grids) > 1 else "calibrated")
    x = result["parameters"]["x1"]
    y = result["parameters"]["x2"]
    ax.set_xlim(x["from"] * xscale, x["to"] * xscale)
    ax.set_ylim(y["from"] * yscale, y["to"] * yscale)
    if x["spacing"] == "log":
        ax.set_xscale("log")
    if y["spacing"] == "log":
        ax.set_yscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_title("bonding boundaries Z = 0")
    ax.grid(True, alpha=0.3)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize="small")
    save_figure(fig, options.out, options.dpi)

# --------------------------------------------------------------------------------------
# Command line
# --------------------------------------------------------------------------------------

def add_figure_options(command, panel_width):
    """--panel-width (inches), --dpi and the required --out of a command that writes one PNG."""
    command.add_argument("--panel-width", type=float, default=panel_width,
                         help="figure width, inches")
    command.add_argument("--dpi", type=int, default=150)
    command.add_argument("--out", required=True, help="PNG file to write")


def build_parser():
    parser = argparse.ArgumentParser(
        prog="coldspray_plot.py", description="PNG figures from a coldspray run's output folder.")
    commands = parser.add_subparsers(dest="command", required=True)

    section = commands.add_parser("section", help="cross-sections coloured by a point field")
    section.add_argument("dir", nargs="+", help="run output folders (panels side by side)")
    section.add_argument("--labels", help="comma-separated run labels (default: folder names)")
    section.add_argument("--times", action="append", required=True,
                         help="times, comma-separated: 10ns,40ns or 8e-8 (seconds) or 0.08us")
    section.add_argument("--field", action="append",
                         help="point field (repeatable; default eqps); vectors: NAME or NAME.x")
    section.add_argument("--bodies", action="append", help="bodies to draw (default all)")
    section.add_argument("--range", action="append",
                         help="colour range [FIELD=]LOW:HIGH; without FIELD= in --field order")
    section.add_argument("--xlim", help="horizontal limits in um, LOW:HIGH")
    section.add_argument("--ylim", help="vertical (z) limits in um, LOW:HIGH")
    section.add_argument("--cmap", default="viridis", help="matplotlib colour map")
    section.add_argument("--cut", choices=["plane", "material"], default="plane",
                         help="3D: the points near y = 0 now (plane) or at t = 0 (material)")
    section.add_argument("--panel-width", type=float, default=3.2, help="inches per panel")
    section.add_argument("--dpi", type=int, default=150)
    section.add_argument("--out", required=True, help="PNG file to write")
    section.set_defaults(run=command_section)

    history = commands.add_parser("history", help="history.csv columns against time")
    history.add_argument("dirs", nargs="+", help="run output folders (overlaid)")
    history.add_argument("--columns", action="append", required=True,
                         help="columns, comma-separated (with --body: BODY.COLUMN)")
    history.add_argument("--body", help="body whose columns to take, e.g. particle")
    history.add_argument("--labels", help="legend labels, comma-separated (default folder names)")
    history.add_argument("--panel-width", type=float, default=6.0, help="figure width, inches")
    history.add_argument("--dpi", type=int, default=150)
    history.add_argument("--out", required=True, help="PNG file to write")
    history.set_defaults(run=command_history)

    vcrit = commands.add_parser("vcrit", help="critical velocity vs diameter (coldspray vcrit)")
    vcrit.add_argument("dir", help="vcrit output folder (vcrit.csv, vcrit_fit.json)")
    vcrit.add_argument("--no-thesis", action="store_true", help="leave out thesis Table 5.4")
    vcrit.add_argument("--no-experiments", action="store_true",
                       help="leave out the experimental 14 um 810 m/s and 30 um 770 m/s")
    vcrit.add_argument("--panel-width", type=float, default=6.0, help="figure width, inches")
    vcrit.add_argument("--dpi", type=int, default=150)
    vcrit.add_argument("--out", required=True, help="PNG file to write")
    vcrit.set_defaults(run=command_vcrit)

    pbcp = commands.add_parser("pbcp-velocity",
                               help="PBCP and v_rest vs impact velocity per size (thesis Fig 5.13)")
    pbcp.add_argument("dir", help="vcrit output folder (vcrit_runs.csv)")
    pbcp.add_argument("--pbcp-tolerance", type=float, default=5.0, help="%% (dashed line)")
    pbcp.add_argument("--rest-tolerance", type=float, default=0.6, help="m/s (dashed lines)")
    pbcp.add_argument("--panel-width", type=float, default=6.0, help="figure width, inches")
    pbcp.add_argument("--dpi", type=int, default=150)
    pbcp.add_argument("--out", required=True, help="PNG file to write")
    pbcp.set_defaults(run=command_pbcp_velocity)

    calibration = commands.add_parser(
        "calibration", help="restitution vs PBCP/ABP per size and the bonding boundaries "
                            "(thesis Figs 5.3, 5.7)")
    calibration.add_argument("dir", help="calibrate output folder (calibration.json, runs.csv)")
    calibration.add_argument("--panel-width", type=float, default=4.0, help="inches per panel")
    calibration.add_argument("--dpi", type=int, default=150)
    calibration.add_argument("--out", required=True, help="PNG file to write")
    calibration.set_defaults(run=command_calibration)

    sweep = commands.add_parser("sweep", help="a sweep's column against its varied key "
                                              "(coldspray sweep; the PD paper's Fig 7)")
    sweep.add_argument("dirs", nargs="+", help="sweep output folders (sweep.csv), overlaid")
    sweep.add_argument("--x", required=True, help="varied key, e.g. contact.peridynamics.beta")
    sweep.add_argument("--y", required=True, help="result column, e.g. particle.cor")
    sweep.add_argument("--labels", help="legend labels, comma-separated (default folder names)")
    sweep.add_argument("--by", help="another varied key: one line per value of it "
                                    "(e.g. bodies.particle.velocity)")
    sweep.add_argument("--panel-width", type=float, default=6.0, help="figure width, inches")
    sweep.add_argument("--dpi", type=int, default=150)
    sweep.add_argument("--out", required=True, help="PNG file to write")
    sweep.set_defaults(run=command_sweep)

    bulk = commands.add_parser("bulk-fracture", help="contact model 2's bulk-fracture curve and "
                                                     "its fit (coldspray bulk-fracture; PD Fig 1)")
    bulk.add_argument("dir", help="bulk-fracture output folder (bulk_fracture.csv, fit.json)")
    bulk.add_argument("--panel-width", type=float, default=6.0, help="figure width, inches")
    bulk.add_argument("--dpi", type=int, default=150)
    bulk.add_argument("--out", required=True, help="PNG file to write")
    bulk.set_defaults(run=command_bulk_fracture)

    mt = commands.add_parser("material-test", help="coldspray material-test curves, with the "
                                                   "published Johnson-Cook formula beside them")
    mt.add_argument("csv", nargs="+", help="material-test CSV files (--out of material-test)")
    mt.add_argument("--labels", help="comma-separated curve labels (default: file names)")
    mt.add_argument("--johnson-cook", help="published constants A,B,n,C,m,T_m[,T_ref,rate0] "
                                           "(MPa, K, 1/s) to draw the formula beside each curve")
    mt.add_argument("--source", help="the constants' publication, for the legend")
    mt.add_argument("--title", help="figure title")
    add_figure_options(mt, 6.0)
    mt.set_defaults(run=command_material_test)

    pull = commands.add_parser("pull-off", help="force against displacement of pull-off tests "
                                                "(coldspray pull-off; PD Fig 11b)")
    pull.add_argument("dirs", nargs="+", help="pull-off output folders (summary.json, "
                                              "pull_off.csv), overlaid")
    pull.add_argument("--labels", help="legend labels, comma-separated (default folder names)")
    pull.add_argument("--panel-width", type=float, default=6.0, help="figure width, inches")
    pull.add_argument("--dpi", type=int, default=150)
    pull.add_argument("--out", required=True, help="PNG file to write")
    pull.set_defaults(run=command_pull_off)

    bond = commands.add_parser("bond-strength", help="bond strength against impact speed and "
                                                     "one splat's radial profile (coldspray "
                                                     "sweep --pull-off)")
    bond.add_argument("dir", help="sweep output folder (sweep.csv, CASE/pull-off/)")
    bond.add_argument("--key", default="bodies.particle.velocity",
                      help="the varied velocity key (default bodies.particle.velocity)")
    bond.add_argument("--profile", help="the case whose radial profile to draw (default: the "
                                        "strongest over its projected area)")
    bond.add_argument("--panel-width", type=float, default=5.0, help="inches per panel")
    bond.add_argument("--dpi", type=int, default=150)
    bond.add_argument("--out", required=True, help="PNG file to write")
    bond.set_defaults(run=command_bond_strength)

    deposit = commands.add_parser("deposit", help="a deposit's thickness map and section "
                                                  "(coldspray deposit)")
    deposit.add_argument("dir", help="deposit run folder (deposit.json, snapshots)")
    deposit.add_argument("--y", default="0um", help="the section's plane y = Y (default 0um)")
    deposit.add_argument("--panel-width", type=float, default=5.0, help="inches per panel")
    deposit.add_argument("--dpi", type=int, default=150)
    deposit.add_argument("--out", required=True, help="PNG file to write")
    deposit.set_defaults(run=command_deposit)

    info = commands.add_parser("info", help="list snapshot times, point fields and columns")
    info.add_argument("dir", help="run output folder")
    info.set_defaults(run=command_info)
    return parser


def main(argv=None):
    options = build_parser().parse_args(argv)
    try:
        options.run(options)
    except PlotError as e:
        print(f"coldspray_plot: error: {e}", file=sys.stderr)
        return EXIT_ERROR
    return 0


if __name__ == "__main__":
    sys.exit(main())
