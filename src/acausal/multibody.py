"""3-D multibody models of robots: ``from_urdf(path)`` (a URDF file) and ``dh_chain(table)``
(a Denavit–Hartenberg table), both building a Model of ``acausal.components.multibody``
parts (see ``acausal.models.robots``). The components themselves are in
``acausal.components.multibody``."""
from .models.robots import JointLimits, dh_chain, from_urdf

__all__ = ["from_urdf", "dh_chain", "JointLimits"]
