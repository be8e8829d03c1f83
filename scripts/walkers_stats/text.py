"""Numbers as the summary's lines and tables print them, and as its JSON holds them; text
written to a file atomically."""
import math
import os


def fmt_p(p):
    """A p-value to read: three decimals, or two significant digits below 0.001."""
    if p is None:
        return "—"
    return f"{p:.3f}" if p >= 0.001 else f"{p:.1e}"


def fmt_interval(interval, fmt="{:.2f}", scale=1.0, unit=""):
    """'[low, high] unit' (scaled), or '(no interval)'."""
    if interval is None:
        return "(no interval)"
    return "[" + ", ".join(fmt.format(scale * v) for v in interval) + "]" + unit


def fmt_generation(g, never=None):
    """A generation number, or 'never' (None, or at least `never`)."""
    return "never" if g is None or never is not None and g >= never - 0.5 else f"{float(g):.0f}"


def fmt_percent(x):
    """A share as '12.3 %', or '—' for none."""
    return "—" if x is None or not math.isfinite(x) else f"{100 * x:.1f} %"


def n_label(*counts):
    """'10' when every case has 10 runs, else '10/9'."""
    return str(counts[0]) if len(set(counts)) == 1 else "/".join(str(c) for c in counts)


def finite_or_null(obj):
    """obj with every non-finite number (a ratio over a zero, say) made null, for JSON."""
    if isinstance(obj, dict):
        return {k: finite_or_null(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [finite_or_null(v) for v in obj]
    if isinstance(obj, float) and not math.isfinite(obj):
        return None
    return obj


def json_interval(interval):
    """An interval as a JSON list, or null."""
    return None if interval is None else [float(v) for v in interval]


def write_atomically(path, text):
    """Write text to path through a temporary file renamed into place."""
    temporary = f"{path}.tmp.{os.getpid()}"
    try:
        with open(temporary, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)
