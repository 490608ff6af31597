"""Typed widgets for the built-in schemes' parameters: prints the server-manager XML of one
property per parameter of each surface scheme in the given scheme folder, shown only while
that scheme is chosen in the Scheme drop-down (CMake puts it into SubdivKitFilters.xml).

    python3 scheme_parameter_widgets.py SCHEMES_DIR

A number (min/max in the scheme file) becomes a slider or spin box in its range, a choice
("choices") a drop-down; the widget sends "scheme:name" and the value to the filter
(SetSchemeParameter, SetSchemeWholeParameter, SetSchemeChoice), which passes them as --param would. Schemes that
are not files in this folder (plugins', SUBDIV_SCHEME_PATH's, a .json chosen as a file)
take their parameters from the Parameters text field, which wins over these widgets."""

import glob
import json
import os
import sys
import re
from xml.sax.saxutils import escape, quoteattr


def surface_parameters(schemes_dir):
    """(scheme, parameter, spec) of every parameter of every surface scheme, by name."""
    for path in sorted(glob.glob(os.path.join(schemes_dir, "*.json"))):
        if os.path.basename(path) == "scheme.schema.json":
            continue
        with open(path) as f:
            scheme = json.load(f)
        if scheme.get("kind", "surface") != "surface":
            continue
        for name, spec in scheme.get("parameters", {}).items():
            yield scheme["name"], name, spec


def shown_for(scheme):
    return (f'<Hints><PropertyWidgetDecorator type="GenericDecorator" mode="visibility" property="Scheme" '
            f'value={quoteattr(scheme)}/></Hints>')


def documentation(scheme, spec):
    return f"<Documentation>{escape(scheme + ': ' + spec.get('description', ''))}</Documentation>"


def property_name(scheme, name):
    """A property name ParaView takes in any form: "loop:beta" -> "loop_beta"."""
    return re.sub(r"[^A-Za-z0-9_]", "_", f"{scheme}_{name}")


def choice_property(scheme, name, spec):
    strings = "".join(f"<String value={quoteattr(c)}/>" for c in spec["choices"])
    return (f'<StringVectorProperty name="{property_name(scheme, name)}" label={quoteattr(name)} '
            f'command="SetSchemeChoice" initial_string={quoteattr(f"{scheme}:{name}")} number_of_elements="1" '
            f'default_values={quoteattr(str(spec["default"]))}><StringListDomain name="list">{strings}'
            f'</StringListDomain>{documentation(scheme, spec)}{shown_for(scheme)}</StringVectorProperty>')


def number_property(scheme, name, spec):
    """A whole-number default (a degree) gets an integer widget, any other a real one."""
    kind, command = ("Int", "SetSchemeWholeParameter") if isinstance(spec["default"], int) else \
        ("Double", "SetSchemeParameter")
    bounds = "".join(f' {k}="{spec[k]!r}"' for k in ("min", "max") if k in spec)
    return (f'<{kind}VectorProperty name="{property_name(scheme, name)}" label={quoteattr(name)} '
            f'command="{command}" initial_string={quoteattr(f"{scheme}:{name}")} number_of_elements="1" '
            f'default_values="{spec["default"]!r}"><{kind}RangeDomain name="range"{bounds}/>'
            f'{documentation(scheme, spec)}{shown_for(scheme)}</{kind}VectorProperty>')


def main(schemes_dir):
    for scheme, name, spec in surface_parameters(schemes_dir):
        print(choice_property(scheme, name, spec) if "choices" in spec else number_property(scheme, name, spec))


if __name__ == "__main__":
    main(sys.argv[1])
