# SPDX-License-Identifier: Apache-2.0
"""Checks an extracted FMU against the rules of the FMI 3.0 standard (section 2.4 "FMI Description Schema",
section 2.5 "FMU Distribution") that an importer relies on, and prints its variables for the C++ harness.

    check_model_description.py EXTRACTED_DIR > variables.txt

Output lines: "token TOKEN", "identifier ID", then "TYPE VR CAUSALITY NAME" per variable. Exit 1 with the broken
rules on stderr."""
import os
import sys
import xml.etree.ElementTree as ET

TYPES = {"Float32", "Float64", "Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32", "Int64", "UInt64",
         "Boolean", "String", "Binary", "Enumeration", "Clock"}
FLOAT = {"Float32", "Float64"}
ORDER = ["ModelExchange", "CoSimulation", "ScheduledExecution", "UnitDefinitions", "TypeDefinitions",
         "LogCategories", "DefaultExperiment", "ModelVariables", "ModelStructure", "Annotations"]
CAUSALITIES = {"parameter", "calculatedParameter", "input", "output", "local", "independent",
               "structuralParameter"}
VARIABILITIES = {"constant", "fixed", "tunable", "discrete", "continuous"}
BASE_UNIT_ATTRIBUTES = {"kg", "m", "s", "A", "K", "mol", "cd", "rad", "factor", "offset"}


def check_variable(v, errors):
    """Causality, variability, initial and start as the standard allows them (Table 'combinations')."""
    name, kind = v.get("name"), v.tag
    causality = v.get("causality", "local")
    variability = v.get("variability", "continuous" if kind in FLOAT else "discrete")
    initial, start = v.get("initial"), v.get("start")
    if causality not in CAUSALITIES or variability not in VARIABILITIES:
        errors.append(f"{name}: causality {causality} or variability {variability} unknown")
    if variability == "continuous" and kind not in FLOAT:
        errors.append(f"{name}: only Float32/Float64 variables may be continuous")
    if causality == "independent":
        if kind not in FLOAT or variability != "continuous" or start is not None or initial is not None:
            errors.append(f"{name}: the independent variable is a continuous float without start or initial")
    elif causality == "input":
        if start is None or initial is not None or variability in ("constant", "fixed", "tunable"):
            errors.append(f"{name}: an input has a start value, no initial, variability discrete or continuous")
    elif causality == "parameter":
        if variability not in ("fixed", "tunable") or start is None or initial not in (None, "exact"):
            errors.append(f"{name}: a parameter is fixed or tunable, initial exact, with a start value")
    elif causality == "output":
        if variability in ("fixed", "tunable") or initial not in (None, "exact", "approx", "calculated"):
            errors.append(f"{name}: illegal output variability {variability} / initial {initial}")
        if initial in (None, "calculated") and start is not None:
            errors.append(f"{name}: a calculated output has no start value")
        if initial in ("exact", "approx") and start is None:
            errors.append(f"{name}: initial {initial} needs a start value")


def check(directory):
    errors = []
    root = ET.parse(os.path.join(directory, "modelDescription.xml")).getroot()  # well-formed, or it raises
    if root.tag != "fmiModelDescription" or root.get("fmiVersion") != "3.0":
        errors.append("root must be fmiModelDescription with fmiVersion 3.0")
    for attribute in ("modelName", "instantiationToken"):
        if not root.get(attribute):
            errors.append(f"fmiModelDescription: {attribute} is required")
    tags = [child.tag for child in root]
    if any(t not in ORDER for t in tags) or tags != sorted(tags, key=ORDER.index) or len(set(tags)) != len(tags):
        errors.append(f"elements out of the schema's order or repeated: {tags}")
    cs = root.find("CoSimulation")
    identifier = cs.get("modelIdentifier") if cs is not None else None
    if not identifier or not identifier.replace("_", "a").isalnum() or identifier[0].isdigit():
        errors.append("CoSimulation needs a modelIdentifier that is a C identifier")
    elif not os.path.isfile(os.path.join(directory, "binaries", "x86_64-linux", identifier + ".so")):
        errors.append(f"binaries/x86_64-linux/{identifier}.so is missing")

    units = [u.get("name") for u in root.iterfind("UnitDefinitions/Unit")]
    if len(units) != len(set(units)):
        errors.append("unit names repeated")
    for u in root.iterfind("UnitDefinitions/Unit"):
        for base in u.iterfind("BaseUnit"):
            if not set(base.attrib) <= BASE_UNIT_ATTRIBUTES:
                errors.append(f"unit {u.get('name')}: unknown BaseUnit attributes {sorted(base.attrib)}")
    categories = [c.get("name") for c in root.iterfind("LogCategories/Category")]
    if len(categories) != len(set(categories)):
        errors.append("log categories repeated")

    variables = list(root.find("ModelVariables"))
    names, references = set(), {}
    for v in variables:
        name, vr = v.get("name"), v.get("valueReference")
        if v.tag not in TYPES or not name or vr is None or not vr.isdigit():
            errors.append(f"variable {name}: unknown type {v.tag} or no name / valueReference")
            continue
        if name in names or int(vr) in references:
            errors.append(f"variable {name}: name or valueReference {vr} not unique")
        names.add(name)
        references[int(vr)] = v
        if v.get("unit") is not None and v.get("unit") not in units:
            errors.append(f"variable {name}: unit {v.get('unit')} not declared in UnitDefinitions")
        check_variable(v, errors)
    if sum(v.get("causality") == "independent" for v in variables) > 1:
        errors.append("more than one independent variable")

    outputs = [int(vr) for vr, v in references.items() if v.get("causality") == "output"]
    listed = [int(o.get("valueReference")) for o in root.iterfind("ModelStructure/Output")]
    if sorted(listed) != sorted(outputs) or len(listed) != len(set(listed)):
        errors.append("ModelStructure/Output must list every output once")
    unknowns = [int(o.get("valueReference")) for o in root.iterfind("ModelStructure/InitialUnknown")]
    needed = [vr for vr in outputs if references[vr].get("initial", "calculated") in ("approx", "calculated")]
    if sorted(unknowns) != sorted(needed):
        errors.append("ModelStructure/InitialUnknown must list every output with initial approx or calculated")

    if errors:
        sys.stderr.write("\n".join(errors) + "\n")
        return 1
    print("token", root.get("instantiationToken"))
    print("identifier", identifier)
    for vr, v in sorted(references.items()):
        print(v.tag, vr, v.get("causality", "local"), v.get("name"))
    return 0


if __name__ == "__main__":
    sys.exit(check(sys.argv[1]))
