"""FMU export of compiled models (``compiled.export_fmu(path, ...)``).

Two backends:

- ``native`` (default): CasADi C code generation + an FMI wrapper in C, compiled with the
  system C compiler; FMI 2.0 or 3.0, model exchange and/or co-simulation; nothing needed on
  the importer's side. See ``acausal.fmu.export`` for what the FMU does and cannot do.
- ``pythonfmu``: an FMI 2.0 co-simulation slave running the compiled model in Python
  (``acausal.fmu.pythonfmu_backend``); models with state events, modes, initial equations
  or termination conditions are refused (FmuExportError): use the native backend for them.
"""
from __future__ import annotations

from pathlib import Path

from ..errors import FmuExportError


def export_fmu(compiled, path, *, fmi_version: str = "2.0", fmu_type: str | None = None,
               backend: str = "native", **options) -> Path:
    """Export ``compiled`` as an FMU at ``path`` (a directory gets ``<model>.fmu``).

    fmi_version  "2.0" or "3.0";
    fmu_type     "me" (model exchange), "cs" (co-simulation) or "both" (one FMU with both);
                 default: "both" for native, "cs" for pythonfmu (all it makes);
    backend      "native" (C, default) or "pythonfmu";
    options      native: ``stop_time`` [s] of the DefaultExperiment (default 1), ``description``.
    Returns the Path of the written .fmu.
    """
    if backend == "native":
        from .export import export_native
        try:
            return export_native(compiled, path, fmi_version=fmi_version,
                                 fmu_type=fmu_type or "both", **options)
        except TypeError as e:
            if "unexpected keyword" in str(e):
                raise FmuExportError(f"export_fmu(backend='native'): {e}") from None
            raise
    if backend == "pythonfmu":
        unsupported = compiled.initial_labels + [f"{c}: terminate" for c, _ in
                                                 compiled.state_events.terminations]
        if unsupported:
            raise FmuExportError(
                f"model '{compiled.name}' has initial equations or termination conditions "
                f"({', '.join(unsupported[:3])}), which the pythonfmu backend does not carry "
                f"(its initialization and steps would ignore them): use backend='native', "
                f"whose FMUs hold the initial equations at initialization and end the run at "
                f"a termination")
        if compiled.has_events:
            owners = sorted({v.component for v in compiled.state_events.indicators
                             + compiled.modes})
            raise FmuExportError(
                f"model '{compiled.name}' has state events or modes (of {', '.join(owners)}); "
                f"the pythonfmu backend does not handle them (its slave would integrate "
                f"across the events and ignore them): use backend='native', whose FMUs "
                f"locate the events (model exchange: event indicators and the event "
                f"iteration in the event update; co-simulation: inside doStep)")
        from .pythonfmu_backend import export_pythonfmu
        return Path(export_pythonfmu(compiled, path, fmi_version=fmi_version,
                                     fmu_type=fmu_type or "cs", **options))
    raise FmuExportError(f"unknown FMU backend {backend!r}; choose 'native' or 'pythonfmu'")


__all__ = ["export_fmu", "FmuExportError"]
