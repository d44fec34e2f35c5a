"""Tools around the FlexibleSliderCrank FMU. `python -m fsc sweep STUDY.toml` runs a parameter study
on Dask (see the user guide, docs/guide/systems.md, "Parameter studies")."""
