"""RAO tables written by `heavesim rao` (docs/rao.md): read one, draw it.

    from heavesim import rao
    r = rao.read("results/semisub_6dof_regular_wave_rao/rao.h5")
    r.channels["heave"].amplitude, r.period, r.channels["heave"].bem_amplitude
    rao.figure(r, "rao.png")

An RAO is per unit wave amplitude, x = Re[RAO a e^{i w t}] with the incident elevation
eta = Re[a e^{i w t}] at the platform's reference point: amplitude in the channel's unit
per metre (rotations in deg/m), phase in degrees, positive when the response leads the
wave crest. `method` is "regular_sweep" (one row per period) or "h1" (one row per Welch
bin in the sea's band, with the coherence of each estimate).
"""
import h5py
import numpy as np

from .result import _attributes, _text

__all__ = ["Rao", "RaoChannel", "read", "figure", "COHERENCE_THRESHOLD"]

COHERENCE_THRESHOLD = 0.9  # H1 points below it are drawn faint: the sea does not explain the response there



class RaoChannel:
    """One channel: arrays per row of the table (NaN where a run failed)."""

    def __init__(self, name, unit, amplitude, phase, coherence=None, bem_amplitude=None, bem_phase=None,
                 bem_line_amplitude=None, bem_line_phase=None):
        self.name = name
        self.unit = unit                      # per unit wave amplitude: "m/m", "deg/m", "N/m"
        self.amplitude = amplitude            # |RAO|
        self.phase = phase                    # deg
        self.coherence = coherence            # H1 only, else None
        self.bem_amplitude = bem_amplitude    # frequency-domain RAO at the rows (modes with BEM data), else None
        self.bem_phase = bem_phase
        self.bem_line_amplitude = bem_line_amplitude  # the same at Rao.bem_frequency
        self.bem_line_phase = bem_line_phase

    @property
    def complex(self):
        """The RAO as complex numbers."""
        return self.amplitude * np.exp(1j * np.radians(self.phase))

    def __repr__(self):
        return f"RaoChannel({self.name!r}, {self.unit}, {len(self.amplitude)} rows)"


class Rao:
    """The contents of a rao.h5: `period` [s] and `frequency` [rad/s] per row, `channels`
    by name in the order given, `bem_frequency` [rad/s] of the frequency-domain line (empty
    without BEM data), and the file's attributes (method, source, platform, heading_rad,
    wave_elevation_channel, phase_convention, frequency_domain_reference)."""

    def __init__(self, path):
        self.path = path
        with h5py.File(path, "r") as f:
            self.attributes = _attributes(f)
            self.period = f["period"][()]
            self.frequency = f["frequency"][()]
            self.bem_frequency = f["bem_frequency"][()] if "bem_frequency" in f else np.array([])
            self.notes = [_text(n) for n in f["note"][()]] if "note" in f else []
            self.channels = {}
            for name in (_text(n) for n in f["channel_names"][()]):
                group = f["channels"][name.lstrip("/").replace("/", ".")]

                def get(key, group=group):
                    return group[key][()] if key in group else None
                self.channels[name] = RaoChannel(name, _text(group["amplitude"].attrs["units"]), get("amplitude"),
                                                 get("phase"), get("coherence"), get("bem_amplitude"), get("bem_phase"),
                                                 get("bem_line_amplitude"), get("bem_line_phase"))
        self.method = self.attributes.get("method")

    def __repr__(self):
        return f"Rao({self.path!r}, {self.method}, {len(self.period)} rows, channels {list(self.channels)})"


def read(path):
    """The RAO table of `path` (a rao.h5 of `heavesim rao`)."""
    return Rao(path)


def figure(rao, path=None, channels=None, coherence_threshold=COHERENCE_THRESHOLD):
    """Amplitude and phase panels per channel against the wave period: points = time domain
    (H1 points with coherence below `coherence_threshold` faint), line = the frequency-domain
    RAO from the BEM data. Saves to `path` when given; returns the matplotlib figure."""
    import matplotlib
    if path is not None:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(channels or rao.channels)
    columns = min(3, len(names))
    rows = -(-len(names) // columns)
    fig, axes = plt.subplots(2 * rows, columns, figsize=(4.6 * columns, 4.4 * rows), squeeze=False, sharex=True)
    h1 = rao.method == "h1"
    finite = np.isfinite(rao.period)
    span = (0.9 * rao.period[finite].min(), 1.1 * rao.period[finite].max()) if finite.any() else None
    for index, name in enumerate(names):
        channel = rao.channels[name]
        top, bottom = axes[2 * (index // columns), index % columns], axes[2 * (index // columns) + 1, index % columns]
        strong = channel.coherence >= coherence_threshold if h1 else np.ones(len(rao.period), bool)
        label = "H1 (irregular run)" if h1 else "regular-wave runs"
        top.plot(rao.period[strong], channel.amplitude[strong], "o", ms=4, color="C0", label=label)
        bottom.plot(rao.period[strong], channel.phase[strong], "o", ms=4, color="C0")
        if h1 and (~strong).any():
            top.plot(rao.period[~strong], channel.amplitude[~strong], "o", ms=3, color="C0", alpha=0.2,
                     label=f"H1, coherence < {coherence_threshold:g}")
            bottom.plot(rao.period[~strong], channel.phase[~strong], "o", ms=3, color="C0", alpha=0.2)
        if channel.bem_line_amplitude is not None and len(rao.bem_frequency):
            order = np.argsort(2 * np.pi / rao.bem_frequency)
            period = (2 * np.pi / rao.bem_frequency)[order]
            keep = (period >= span[0]) & (period <= span[1]) if span else np.ones(len(period), bool)
            top.plot(period[keep], channel.bem_line_amplitude[order][keep], "-", color="C3", lw=1.2,
                     label="frequency domain (BEM)")
            bottom.plot(period[keep], channel.bem_line_phase[order][keep], "-", color="C3", lw=1.2)
        top.set_title(name, fontsize=10)
        top.set_ylabel(f"|RAO| [{channel.unit}]")
        bottom.set_ylabel("phase [deg]")
        bottom.set_ylim(-185, 185)
        bottom.set_yticks([-180, -90, 0, 90, 180])
        for axis in (top, bottom):
            axis.grid(True, alpha=0.3)
            if span:
                axis.set_xlim(*span)
        if index == 0:
            top.legend(fontsize=8)
    for index in range(len(names), rows * columns):
        axes[2 * (index // columns), index % columns].set_visible(False)
        axes[2 * (index // columns) + 1, index % columns].set_visible(False)
    for axis in axes[-1]:
        axis.set_xlabel("wave period [s]")
    heading = np.degrees(float(rao.attributes.get("heading_rad", 0.0)))
    how = "H1 from one irregular run" if h1 else f"regular-wave sweep, a = {rao.attributes.get('wave_amplitude_m', 1):g} m"
    fig.suptitle(f"RAO of {rao.attributes.get('platform', '')}: {how}, heading {heading:.0f} deg; phase relative to "
                 f"the wave crest at the reference point", fontsize=10)
    fig.tight_layout()
    if path is not None:
        fig.savefig(path, dpi=110)
        plt.close(fig)
    return fig
