"""The component library, one module per domain (Modelica names and sign conventions)."""
