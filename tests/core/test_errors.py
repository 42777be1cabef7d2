"""The hierarchy of acausal.errors: one base, each error printed under its own class name, and
the errors that are also Python's own kind caught by ``except`` of that kind."""
import traceback

import pytest

from acausal import errors
from acausal.errors import (AcausalError, AnalysisError, DisabledPortError, FmuExportError,
                            FmuPathError, OCPError, ParameterError, SingularModelError,
                            SolveError, StructureError, VariableNameError, did_you_mean)

CLASSES = [name for name in errors.__all__ if isinstance(getattr(errors, name), type)
           and not issubclass(getattr(errors, name), Warning)]


def test_the_warnings_are_user_warnings_not_errors():
    assert issubclass(errors.SmoothFormWarning, UserWarning)
    assert not issubclass(errors.SmoothFormWarning, AcausalError)


def instance(cls, message):
    return cls(message, "Infeasible_Problem_Detected") if cls is SolveError else cls(message)


@pytest.mark.parametrize("name", CLASSES)
def test_every_error_prints_its_own_class_name(name):
    cls = getattr(errors, name)
    assert cls.__name__ == name and cls.__module__ == "acausal.errors"
    assert issubclass(cls, AcausalError)
    err = instance(cls, "no variable 'x'")
    assert str(err) == "no variable 'x'"
    assert repr(err).startswith(f"{name}(")
    assert traceback.format_exception_only(cls, err) == [
        f"acausal.errors.{name}: no variable 'x'\n"]


@pytest.mark.parametrize("cls, builtin", [(VariableNameError, KeyError),
                                          (ParameterError, ValueError),
                                          (DisabledPortError, AttributeError),
                                          (FmuPathError, FileNotFoundError),
                                          (AnalysisError, ValueError), (OCPError, ValueError)])
def test_errors_that_are_also_pythons_own_kind(cls, builtin):
    assert issubclass(cls, builtin)
    with pytest.raises(builtin, match="the part at fault"):
        raise instance(cls, "the part at fault")


def test_specialized_errors_are_caught_as_their_parents():
    assert issubclass(SingularModelError, StructureError)
    assert issubclass(SolveError, OCPError)
    assert issubclass(FmuPathError, FmuExportError)


def test_variable_name_error_reads_as_its_message_not_a_quoted_key():
    err = VariableNameError("no variable 'mass.ss' in model 'osc'")
    assert str(err) == "no variable 'mass.ss' in model 'osc'"
    assert str(VariableNameError()) == ""


def test_solve_error_keeps_ipopts_status_and_the_last_iterate():
    last = object()
    err = SolveError("IPOPT failed: Infeasible_Problem_Detected", "Infeasible_Problem_Detected",
                     last)
    assert (err.status, err.solution) == ("Infeasible_Problem_Detected", last)
    assert SolveError("failed", "Maximum_Iterations_Exceeded").solution is None


def test_did_you_mean_lists_the_closest_names():
    assert did_you_mean("spring.cc", ["spring.c", "mass.m", "damper.d"]) == \
        "; did you mean 'spring.c'?"
    assert did_you_mean("mas.s", ["mass.s", "mass.v", "mass.m"]) == \
        "; did you mean 'mass.s', 'mass.v', 'mass.m'?"
    assert did_you_mean("zzz", ["mass.s"]) == ""
