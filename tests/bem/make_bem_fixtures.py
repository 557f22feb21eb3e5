#!/usr/bin/python3
"""Writes the BEMIO HDF5 and Capytaine NetCDF4 fixtures of tests/bem/ and the malformed
ones of tests/bad_bem/ from the MSS semi's WAMIT files (data/mss_semisub/semisub.1, .3,
.hst), with numpy and h5py only (Debian python3-numpy, python3-h5py):

    /usr/bin/python3 tests/bem/make_bem_fixtures.py

The conversion is done here, independently of the C++ readers, so that the tests that
compare the readers against the WAMIT reader check both the scalings and the layouts:

  WAMIT (ULEN = 1 m, docs/physics/hydrodynamics.md §10):  A = rho A_bar, B = rho w B_bar,
      X = rho g X_bar, C = rho g C_bar, modes 1..6 = surge .. yaw, e^{+i w t}.
  BEMIO (docs/physics/hydrodynamics.md §10): stored nondimensional, A/rho, B/(rho w),
      X/(rho g), C/(rho g), scaled = 0; shapes (6, 6 Nb, Nf), (6, Nh, Nf) in C order
      (the MATLAB-permuted layout of writeBEMIOH5.m); headings in degrees.
  Capytaine (cpt.assemble_dataset + separate_complex_values, written as netCDF4):
      dimensional; added_mass (omega, radiating_dof, influenced_dof) with
      A_ij = added_mass[omega, radiating_dof = j, influenced_dof = i]; excitation =
      diffraction_force + Froude_Krylov_force with dims (omega, wave_direction,
      influenced_dof, complex = [re, im]) in Capytaine's e^{-i w t}, i.e. the complex
      conjugate of WAMIT's; omega = 0 and omega = inf rows for A(0) and A(inf) with
      NaN excitation (no diffraction problem there); headings in radians.

WAMIT's .3 holds the total excitation only: the Capytaine split into Froude-Krylov and
diffraction parts (FK = 0.3 X, diffraction = 0.7 X) is made up; only their sum is data.
To keep the files small, the excitation keeps 4 of the 19 headings, and the malformed
files every fourth frequency.
"""
import pathlib

import h5py
import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[2]
GOOD = ROOT / "tests" / "bem"
BAD = ROOT / "tests" / "bad_bem"
RHO, G = 1025.0, 9.81
HEADINGS_DEG = [0.0, 30.0, 90.0, 180.0]
DOF_NAMES = ["Surge", "Sway", "Heave", "Roll", "Pitch", "Yaw"]


def read_semisub():
    """Dimensional A(0), A(inf), A(w), B(w), X(w, beta), C of the MSS semi, w ascending."""
    base = ROOT / "data" / "mss_semisub" / "semisub"
    zero, infinite = np.zeros((6, 6)), np.zeros((6, 6))
    added, damping = {}, {}
    for line in open(f"{base}.1"):
        v = line.split()
        if not v:
            continue
        period, i, j = float(v[0]), int(v[1]) - 1, int(v[2]) - 1
        if period == -1.0:
            zero[i, j] = RHO * float(v[3])
        elif period == 0.0:
            infinite[i, j] = RHO * float(v[3])
        else:
            w = 2 * np.pi / period
            added.setdefault(period, np.zeros((6, 6)))[i, j] = RHO * float(v[3])
            damping.setdefault(period, np.zeros((6, 6)))[i, j] = RHO * w * float(v[4])
    periods = sorted(added, reverse=True)  # frequencies ascending
    w = np.array([2 * np.pi / p for p in periods])
    A = np.array([added[p] for p in periods])  # (Nf, 6, 6)
    B = np.array([damping[p] for p in periods])
    X = np.zeros((len(HEADINGS_DEG), len(periods), 6), dtype=complex)  # (Nh, Nf, 6)
    for line in open(f"{base}.3"):
        v = line.split()
        if not v or float(v[1]) not in HEADINGS_DEG:
            continue
        h, n, i = HEADINGS_DEG.index(float(v[1])), periods.index(float(v[0])), int(v[2]) - 1
        X[h, n, i] = RHO * G * complex(float(v[5]), float(v[6]))
    C = np.zeros((6, 6))
    for line in open(f"{base}.hst"):
        v = line.split()
        if v:
            C[int(v[0]) - 1, int(v[1]) - 1] = RHO * G * float(v[2])
    return dict(w=w, zero=zero, infinite=infinite, A=A, B=B, X=X, C=C)


# ---- BEMIO ------------------------------------------------------------------------------

def bemio_datasets(d, reversed_dims=False):
    """{path: (array, attributes)} of a BEMIO file; reversed_dims writes every array with
    its dimensions in the opposite order (as MATLAB does without the permute)."""
    w = d["w"]
    A = np.transpose(d["A"], (1, 2, 0)) / RHO                 # (6, 6, Nf)
    B = np.transpose(d["B"], (1, 2, 0)) / (RHO * w)           # (6, 6, Nf)
    X = np.transpose(d["X"], (2, 0, 1)) / (RHO * G)           # (6, Nh, Nf)
    arrange = (lambda a: np.ascontiguousarray(a.T)) if reversed_dims else (lambda a: a)
    coeffs = "/body1/hydro_coeffs/"
    return {
        "/bem_data/code": ("WAMIT", {}),
        "/simulation_parameters/g": (G, {"units": "m/s^2"}),
        "/simulation_parameters/rho": (RHO, {"units": "kg/m^3"}),
        "/simulation_parameters/w": (w, {"units": "rad/s", "description": "wave frequencies"}),
        "/simulation_parameters/T": (2 * np.pi / w, {"units": "s", "description": "wave periods"}),
        "/simulation_parameters/wave_dir": (np.array(HEADINGS_DEG), {"units": "deg"}),
        "/simulation_parameters/water_depth": ("infinite", {"units": "m"}),
        "/simulation_parameters/scaled": (0, {"description": "0: nondimensional (A/rho, B/(rho w), X/(rho g), C/(rho g))"}),
        "/body1/properties/name": ("semisub", {}),
        "/body1/properties/body_number": (1, {}),
        "/body1/properties/dof": (6, {}),
        coeffs + "linear_restoring_stiffness": (arrange(d["C"] / (RHO * G)), {"units": "m^2, m^3, m^4"}),
        coeffs + "added_mass/all": (arrange(A), {"units": "m^3, m^4, m^5"}),
        coeffs + "added_mass/inf_freq": (arrange(d["infinite"] / RHO), {"units": "m^3, m^4, m^5"}),
        coeffs + "radiation_damping/all": (arrange(B), {"units": "m^3, m^4, m^5"}),
        coeffs + "excitation/re": (arrange(X.real), {"units": "m^2, m^3"}),
        coeffs + "excitation/im": (arrange(X.imag), {"units": "m^2, m^3"}),
        coeffs + "excitation/mag": (arrange(np.abs(X)), {"units": "m^2, m^3"}),
        coeffs + "excitation/phase": (arrange(np.angle(X)), {"units": "rad"}),
    }


def write_h5(path, datasets):
    with h5py.File(path, "w") as f:
        for name, (value, attributes) in datasets.items():
            dataset = f.create_dataset(name, data=value)
            for key, text in attributes.items():
                dataset.attrs[key] = text


# ---- Capytaine --------------------------------------------------------------------------

def capytaine_variables(d, transposed=False, omega=None):
    """{name: (array, dims, attributes)} of a Capytaine dataset; transposed writes the
    variables with other dimension orders and complex = [im, re], which a reader that
    looks the dimensions up must not notice."""
    w = d["w"]
    nan6 = np.full((1, 6, 6), np.nan)
    omega_all = np.concatenate([[0.0], w, [np.inf]]) if omega is None else omega
    # A_ij = added_mass[radiating_dof = j, influenced_dof = i]: transpose each matrix.
    A = np.concatenate([d["zero"][None], d["A"], d["infinite"][None]]).transpose(0, 2, 1)
    B = np.concatenate([np.zeros((1, 6, 6)), d["B"], np.zeros((1, 6, 6))]).transpose(0, 2, 1)
    X = np.conj(np.transpose(d["X"], (1, 0, 2)))  # (Nf, Nh, 6), e^{-i w t}
    nan_row = np.full((1,) + X.shape[1:], np.nan + 1j * np.nan)
    X = np.concatenate([nan_row, X, nan_row])
    parts = {"Froude_Krylov_force": 0.3 * X, "diffraction_force": X - 0.3 * X}
    labels = ["im", "re"] if transposed else ["re", "im"]
    split = lambda z: np.stack([z.imag, z.real] if transposed else [z.real, z.imag], axis=-1)
    variables = {
        "omega": (omega_all, ("omega",), {"units": "rad/s", "long_name": "Angular frequency"}),
        "wave_direction": (np.radians(HEADINGS_DEG), ("wave_direction",), {"units": "rad"}),
        "radiating_dof": (DOF_NAMES, ("radiating_dof",), {}),
        "influenced_dof": (DOF_NAMES, ("influenced_dof",), {}),
        "complex": (labels, ("complex",), {}),
        "rho": (RHO, (), {}),
        "g": (G, (), {}),
        "water_depth": (np.inf, (), {}),
        "body_name": ("semisub", (), {}),
        "hydrostatic_stiffness": (d["C"], ("influenced_dof", "radiating_dof"), {}),
    }
    if transposed:
        variables["added_mass"] = (A.transpose(2, 1, 0), ("influenced_dof", "radiating_dof", "omega"), {})
        variables["radiation_damping"] = (B.transpose(1, 0, 2), ("radiating_dof", "omega", "influenced_dof"), {})
        for name, z in parts.items():  # (complex, influenced_dof, omega, wave_direction)
            variables[name] = (split(z).transpose(3, 2, 0, 1), ("complex", "influenced_dof", "omega", "wave_direction"), {})
    else:
        variables["added_mass"] = (A, ("omega", "radiating_dof", "influenced_dof"), {})
        variables["radiation_damping"] = (B, ("omega", "radiating_dof", "influenced_dof"), {})
        for name, z in parts.items():
            variables[name] = (split(z), ("omega", "wave_direction", "influenced_dof", "complex"), {})
    return variables


def write_nc(path, variables):
    """netCDF4 layout: every dimension a coordinate dataset made a dimension scale, every
    variable's axes attached to its dimensions' scales."""
    with h5py.File(path, "w") as f:
        for name, (value, dims, attributes) in variables.items():
            if isinstance(value, str) or (isinstance(value, list) and isinstance(value[0], str)):
                f.create_dataset(name, data=value, dtype=h5py.string_dtype())
            else:
                f.create_dataset(name, data=np.asarray(value, dtype=float))
            for key, text in attributes.items():
                f[name].attrs[key] = text
        for name, (value, dims, attributes) in variables.items():
            if dims == (name,):
                f[name].make_scale(name)
        for name, (value, dims, attributes) in variables.items():
            if dims != (name,):
                for axis, dim in enumerate(dims):
                    f[name].dims[axis].attach_scale(f[dim])


# ---- fixtures ---------------------------------------------------------------------------

def write_text(path, text):
    path.write_text(text)


def truncated_copy(source, target):
    data = source.read_bytes()
    target.write_bytes(data[: len(data) // 2])


def main():
    d = read_semisub()
    write_h5(GOOD / "semisub.h5", bemio_datasets(d))
    write_h5(GOOD / "semisub_reversed_dims.h5", bemio_datasets(d, reversed_dims=True))
    write_nc(GOOD / "semisub.nc", capytaine_variables(d))
    write_nc(GOOD / "semisub_transposed.nc", capytaine_variables(d, transposed=True))

    # The malformed files keep every fourth frequency (they serve no run).
    d = dict(d, w=d["w"][::4], A=d["A"][::4], B=d["B"][::4], X=d["X"][:, ::4])
    # BEMIO: one fault each.
    write_text(BAD / "bemio_not_hdf5.h5", "PER I J A B\n4.5 1 1 7.97e3 4.45e3\n")
    truncated_copy(GOOD / "semisub.h5", BAD / "bemio_truncated.h5")
    coeffs = "/body1/hydro_coeffs/"
    faults = {}
    b = bemio_datasets(d); del b[coeffs + "added_mass/inf_freq"]; faults["bemio_missing_inf_freq"] = b
    b = bemio_datasets(d); a, at = b[coeffs + "radiation_damping/all"]
    b[coeffs + "radiation_damping/all"] = (a[:, :, :-1], at); faults["bemio_frequency_count_mismatch"] = b
    b = bemio_datasets(d); a, at = b[coeffs + "radiation_damping/all"]; a = a.copy(); a[2, 2, 4] = np.nan
    b[coeffs + "radiation_damping/all"] = (a, at); faults["bemio_nan_damping"] = b
    b = bemio_datasets(d); a, at = b[coeffs + "added_mass/all"]; a = a.copy()
    a[0, 4, 3] = a[4, 0, 3] + 0.1 * np.sqrt(a[0, 0, 3] * a[4, 4, 3])  # beyond the 2 % symmetry tolerance
    b[coeffs + "added_mass/all"] = (a, at); faults["bemio_asymmetric_added_mass"] = b
    b = bemio_datasets(d); b["/simulation_parameters/scaled"] = (2, {}); faults["bemio_scaled_flag_invalid"] = b
    b = bemio_datasets(d); b["/simulation_parameters/w"] = (d["w"] / (2 * np.pi), {"units": "Hz"})
    faults["bemio_wrong_units"] = b
    b = bemio_datasets(d); del b[coeffs + "excitation/im"]; faults["bemio_missing_excitation_im"] = b
    # Only the w = 0 entry: no finite frequency to excite (found by fuzzing: the excitation
    # reader returned no frequency at all).
    b = bemio_datasets(dict(d, w=d["w"][:1], A=d["A"][:1], B=d["B"][:1], X=d["X"][:, :1]))
    b["/simulation_parameters/w"] = (np.array([0.0]), {"units": "rad/s"}); faults["bemio_only_zero_frequency"] = b
    for name, datasets in faults.items():
        write_h5(BAD / f"{name}.h5", datasets)

    # Capytaine: one fault each.
    write_text(BAD / "capytaine_not_netcdf.nc", "CDF not really\n")
    truncated_copy(GOOD / "semisub.nc", BAD / "capytaine_truncated.nc")
    faults = {}
    v = capytaine_variables(d)
    for name in ("added_mass", "radiation_damping", "Froude_Krylov_force", "diffraction_force"):
        value, dims, at = v[name]
        v[name] = (value[:-1], dims, at)
    v["omega"] = (v["omega"][0][:-1], ("omega",), v["omega"][2]); faults["capytaine_no_infinite_frequency"] = v
    v = capytaine_variables(d); v["radiating_dof"] = (["Surge", "Sway", "Heaving", "Roll", "Pitch", "Yaw"],
                                                      ("radiating_dof",), {})
    faults["capytaine_unknown_dof"] = v
    v = capytaine_variables(d); value, dims, at = v["diffraction_force"]; value = value.copy()
    value[5, 1, 2, 0] = np.nan; v["diffraction_force"] = (value, dims, at); faults["capytaine_nan_diffraction"] = v
    v = capytaine_variables(d); value, dims, at = v["added_mass"]; value = value.copy()
    value[3, 4, 0] = value[3, 0, 4] + 0.1 * np.sqrt(value[3, 0, 0] * value[3, 4, 4])
    v["added_mass"] = (value, dims, at); faults["capytaine_asymmetric_added_mass"] = v
    v = capytaine_variables(d); v["wave_direction"] = (np.array(HEADINGS_DEG), ("wave_direction",), {"units": "deg"})
    faults["capytaine_wrong_units"] = v
    v = capytaine_variables(d); del v["radiation_damping"]; faults["capytaine_missing_radiation_damping"] = v
    v = capytaine_variables(d); value, dims, at = v["radiation_damping"]
    v["radiation_damping"] = (value[:, :, :3], dims, at); faults["capytaine_wrong_shape"] = v
    for name, variables in faults.items():
        write_nc(BAD / f"{name}.nc", variables)


if __name__ == "__main__":
    main()
