"""The data of a YAML file that a .xacro file reads with `load_yaml(...)`, read safely.

The text is composed by `yamlsafe` (no aliases, no tags but xacro's units, at most 20,000
values nested 10 deep) and turned into `YamlMap`, `YamlList` and plain scalars, never into
objects. xacro's unit tags are read as xacro reads them, the value worked out by dhsym's own
expression evaluator and scaled: `!radians`, `!degrees`, `!meters`, `!millimeters`, `!foot`,
`!inches` (so `!degrees 180` is π).

>>> data = yaml_data("joint:\\n  min: !degrees -180\\n  names: [a, b]\\n  enabled: true\\n", "limits.yaml")
>>> data["joint"]["min"], data["joint"]["names"][1], data["joint"]["enabled"]
(-3.141592653589793, 'b', True)
>>> yaml_data("x: !!python/name:os.system", "bad.yaml")
Traceback (most recent call last):
dhsym.errors.UserError: bad.yaml:1:4: YAML tags (!!python/name:os.system) are not allowed in xacro YAML files
"""
from __future__ import annotations

import math

import yaml

from ..errors import UserError
from .xacroexpr import Refused, YamlList, YamlMap, evaluate
from .yamlsafe import compose, mark_location

UNITS = {"!radians": 1.0, "!degrees": math.pi / 180, "!meters": 1.0, "!millimeters": 0.001, "!foot": 0.3048,
         "!inches": 0.0254}
WHAT = "xacro YAML file"


def yaml_data(text: str, filename: str):
    """The data of one YAML document (see the module's docstring)."""
    if not text.strip():
        return None  # xacro's load_yaml gives None for an empty file
    return _data(compose(text, filename, frozenset(UNITS), WHAT), filename)


def _data(node, filename: str):
    if isinstance(node, yaml.MappingNode):
        return YamlMap((_data(key, filename), _data(value, filename)) for key, value in node.value)
    if isinstance(node, yaml.SequenceNode):
        return YamlList(_data(item, filename) for item in node.value)
    if node.tag in UNITS:
        try:
            return float(evaluate(node.value, {})) * UNITS[node.tag]
        except (Refused, TypeError, ValueError) as error:
            raise UserError(f"{node.tag} {node.value}: {error}", mark_location(filename, node.start_mark)) from None
    try:
        return yaml.constructor.SafeConstructor().construct_object(node)
    except (yaml.YAMLError, ValueError) as error:
        raise UserError(f"YAML value {node.value[:40]!r}: {' '.join(str(error).split())[:120]}",
                        mark_location(filename, node.start_mark)) from None
