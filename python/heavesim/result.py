"""Reading heavesim result files (docs/result-file.md, docs/python.md).

A Result reads lazily with h5py: opening reads the names, units and attributes; a
channel's values are read when first asked for. A file whose run is still writing it,
or whose writer was killed, opens too; refresh() reopens it and sees the samples
written since. Only the first `samples_written` rows of every series are whole samples
(the rest is space reserved for the run), so every array returned here stops there.
"""
import numpy
import h5py


def _text(value):
    """An attribute as Python text or number (h5py gives bytes for fixed strings)."""
    if isinstance(value, bytes):
        return value.decode("utf-8")
    if isinstance(value, numpy.ndarray) and value.shape == ():
        return value.item()
    if isinstance(value, numpy.generic):
        return value.item()
    return value


def _attributes(node):
    return {name: _text(value) for name, value in node.attrs.items() if not name.startswith("_")}


def _open_file(path):
    # heavesim's writer takes no file lock: a plain open works while it writes. A file
    # written in HDF5's SWMR mode by another program, still open or killed, opens as a
    # SWMR reader.
    try:
        return h5py.File(path, "r")
    except OSError:
        return h5py.File(path, "r", swmr=True)


class Channel:
    """One recorded time series: `values` (numpy, one row per sample), `units`,
    `description`, `statistics` (the evaluation window's response statistics: field ->
    value for a scalar series, field -> array over the columns otherwise) and every
    attribute in `attributes` (whole-record minimum, maximum, mean, standard_deviation)."""

    def __init__(self, result, path):
        self._result = result
        self.path = path
        self._values = None

    @property
    def _dataset(self):
        return self._result._file[self.path]

    @property
    def attributes(self):
        return _attributes(self._dataset)

    @property
    def units(self):
        return _text(self._dataset.attrs.get("units", ""))

    @property
    def description(self):
        return _text(self._dataset.attrs.get("description", ""))

    @property
    def shape(self):
        return (self._result.samples,) + self._dataset.shape[1:]

    @property
    def values(self):
        if self._values is None:
            self._values = self._dataset[: self._result.samples]
        return self._values

    @property
    def statistics(self):
        records = self._dataset.attrs.get("statistics")
        if records is None:
            return {}
        records = numpy.asarray(records)
        scalar = len(self._dataset.shape) == 1
        return {name: (records[name][0].item() if scalar else numpy.array(records[name]))
                for name in records.dtype.names}

    def __array__(self, dtype=None):
        return numpy.asarray(self.values, dtype=dtype)

    def __repr__(self):
        return f"Channel({self.path!r}, shape={self.shape}, units={self.units!r})"


class Result:
    """A heavesim result file (a run, a kinematic analysis or an equilibrium).

    r.time            /time [s], the samples written
    r.channels        {"/joints/hook/reaction_force": Channel, ...}: every time series
    r["joints/compensator/position"]   that channel's values (a leading "/" optional)
    r.summary         /summary's attributes (meaningful once r.complete)
    r.attributes      the root attributes (case name, version, failure, ...)
    r.complete        the run reached its end and wrote everything
    r.samples         whole samples on disk (the root attribute samples_written)
    r.refresh()       sees what a running writer has added since
    """

    def __init__(self, path):
        self.path = str(path)
        self._file = _open_file(self.path)
        self._channels = None
        self._read_header()

    def _read_header(self):
        self.attributes = _attributes(self._file)
        has_time = "time" in self._file
        extent = self._file["time"].shape[0] if has_time else 0
        self.samples = int(self.attributes.get("samples_written", extent))

    # --- what the file holds -------------------------------------------------
    @property
    def complete(self):
        return bool(self.attributes.get("complete", 0))

    @property
    def summary(self):
        return _attributes(self._file["summary"]) if "summary" in self._file else {}

    @property
    def time(self):
        return self._file["time"][: self.samples] if "time" in self._file else numpy.empty(0)

    @property
    def channels(self):
        if self._channels is None:
            self._channels = {}
            if "time" in self._file:
                extent = self._file["time"].shape[0]

                def visit(name, node):
                    # A time series: numeric, one row per sample, with units (as `heavesim stats`).
                    if (isinstance(node, h5py.Dataset) and name != "time" and node.ndim in (1, 2)
                            and node.shape[0] == extent and "units" in node.attrs
                            and node.dtype.kind == "f"):
                        self._channels["/" + name] = Channel(self, "/" + name)

                self._file.visititems(visit)
        return self._channels

    def channel(self, path):
        key = path if path.startswith("/") else "/" + path
        if key == "/time":
            return Channel(self, "/time")
        try:
            return self.channels[key]
        except KeyError:
            raise KeyError(f"{self.path} has no channel {key}; it has {len(self.channels)}: "
                           + ", ".join(sorted(self.channels)[:8]) + ", ...") from None

    def __getitem__(self, path):
        return self.channel(path).values

    def __contains__(self, path):
        key = path if path.startswith("/") else "/" + path
        return key == "/time" or key in self.channels

    def _model_order(self, group):
        # Groups list alphabetically; the writer records the model's (topological) order.
        if group not in self._file:
            return []
        order = _text(self._file[group].attrs.get("order", ""))
        names = [name for name in order.split(",") if name in self._file[group]]
        return names or list(self._file[group])

    @property
    def bodies(self):
        """Body names in the model's order (those with recorded channels)."""
        return self._model_order("bodies")

    @property
    def joints(self):
        """Joint names in the model's order (those with recorded channels)."""
        return self._model_order("joints")

    @property
    def case_yaml(self):
        if "case/yaml" not in self._file:
            return None
        return _text(self._file["case/yaml"][()])

    # --- a file being written --------------------------------------------------
    def refresh(self):
        """Re-reads samples_written and the attributes a running writer has changed:
        HDF5 caches what a reader has read, so the file is opened anew."""
        channels = list(self._channels) if self._channels is not None else None
        self._file.close()
        self._file = _open_file(self.path)
        self._read_header()
        if channels is not None:
            self._channels = {path: Channel(self, path) for path in channels}
        return self

    def close(self):
        self._file.close()

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.close()

    def __repr__(self):
        state = "complete" if self.complete else "incomplete"
        return f"Result({self.path!r}, {self.samples} samples, {len(self.channels)} channels, {state})"
