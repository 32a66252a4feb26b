"""The project's public files agree with each other and with their formats.
Usage: project_files.py SOURCE_DIR

- CITATION.cff is valid Citation File Format 1.2.0: YAML, the required keys
  with the types the format gives them, no key the format does not know, and
  a `references:` entry for the paper the toolkit reproduces. (When the
  `cffconvert` program is on PATH, its --validate must pass too.)
- The version is set once, in CMakeLists.txt's project(... VERSION ...):
  the top entry of NEWS.md and CITATION.cff's `version` must equal it.
- LICENSE is the GPL, version 3, as CITATION.cff and the README say.
Prints each finding and exits 1 if any."""
import datetime
import os
import re
import shutil
import subprocess
import sys

import yaml

# Citation File Format 1.2.0 (https://citation-file-format.github.io/): the
# keys it defines at the root, for a reference and for a person or entity.
ROOT_KEYS = {"abstract", "authors", "cff-version", "commit", "contact", "date-released", "doi", "identifiers",
             "keywords", "license", "license-url", "message", "preferred-citation", "references", "repository",
             "repository-artifact", "repository-code", "title", "type", "url", "version"}
ROOT_REQUIRED = {"authors", "cff-version", "message", "title"}
REFERENCE_KEYS = {"abbreviation", "abstract", "authors", "collection-doi", "collection-title", "collection-type",
                  "commit", "conference", "contact", "copyright", "data-type", "database", "database-provider",
                  "date-accessed", "date-downloaded", "date-published", "date-released", "department", "doi",
                  "edition", "editors", "editors-series", "end", "entry", "filename", "format", "identifiers",
                  "institution", "isbn", "issn", "issue", "issue-date", "issue-title", "journal", "keywords",
                  "languages", "license", "license-url", "loc-end", "loc-start", "location", "medium", "month",
                  "nihmsid", "notes", "number", "number-volumes", "pages", "patent-states", "pmcid", "publisher",
                  "recipients", "repository", "repository-artifact", "repository-code", "scope", "section",
                  "senders", "start", "status", "term", "thesis-type", "title", "translators", "type", "url",
                  "version", "volume", "volume-title", "year", "year-original"}
REFERENCE_REQUIRED = {"authors", "title", "type"}
REFERENCE_INTEGERS = {"end", "start", "volume", "year", "year-original", "month", "pages", "loc-end", "loc-start",
                      "number-volumes"}
PERSON_KEYS = {"address", "affiliation", "alias", "city", "country", "email", "family-names", "fax",
               "given-names", "name-particle", "name-suffix", "orcid", "post-code", "region", "tel", "website"}
ENTITY_KEYS = {"address", "alias", "city", "country", "date-end", "date-start", "email", "fax", "location", "name",
               "orcid", "post-code", "region", "tel", "website"}
DOI = re.compile(r"^10\.\d{4,9}(\.\d+)?/[A-Za-z0-9:/_;\-.()\[\]\\]+$")
DATE = re.compile(r"^[0-9]{4}-(0[1-9]|1[012])-(0[1-9]|[12][0-9]|3[01])$")

problems = []


def problem(text):
    problems.append(text)
    print("FAILED: " + text)


def nonempty_string(value):
    return isinstance(value, str) and len(value) > 0


def check_authors(where, authors):
    if not isinstance(authors, list) or not authors:
        problem(f"{where}: authors must be a non-empty list")
        return
    for i, a in enumerate(authors):
        if not isinstance(a, dict) or not a:
            problem(f"{where}: author {i + 1} must be a mapping")
            continue
        keys = set(a)
        if "name" in keys:  # an entity
            if keys - ENTITY_KEYS:
                problem(f"{where}: author {i + 1} (entity) has unknown keys {sorted(keys - ENTITY_KEYS)}")
        elif keys - PERSON_KEYS:
            problem(f"{where}: author {i + 1} (person) has unknown keys {sorted(keys - PERSON_KEYS)}")
        for k, v in a.items():
            if not nonempty_string(v):
                problem(f"{where}: author {i + 1}'s {k} must be a non-empty string, not {v!r}")


def check_common(where, entry):
    for key in ("doi",):
        if key in entry and not (isinstance(entry[key], str) and DOI.match(entry[key])):
            problem(f"{where}: {key} {entry[key]!r} is not a bare DOI (10.NNNN/...)")
    for key in ("date-released", "date-published"):
        if key in entry:
            value = entry[key]
            value = value.isoformat() if isinstance(value, datetime.date) else value
            if not (isinstance(value, str) and DATE.match(value)):
                problem(f"{where}: {key} {entry[key]!r} is not YYYY-MM-DD")
    if "version" in entry and not (nonempty_string(entry["version"]) or isinstance(entry["version"], (int, float))):
        problem(f"{where}: version must be a string or a number")
    if "keywords" in entry and not (isinstance(entry["keywords"], list) and entry["keywords"]
                                    and all(nonempty_string(k) for k in entry["keywords"])):
        problem(f"{where}: keywords must be a non-empty list of strings")


def check_citation(path):
    with open(path, encoding="utf-8") as f:
        cff = yaml.safe_load(f)
    if not isinstance(cff, dict):
        problem(f"{path}: not a YAML mapping")
        return None
    missing = ROOT_REQUIRED - set(cff)
    if missing:
        problem(f"{path}: required keys missing: {sorted(missing)}")
    unknown = set(cff) - ROOT_KEYS
    if unknown:
        problem(f"{path}: keys CFF 1.2.0 does not define: {sorted(unknown)}")
    if cff.get("cff-version") != "1.2.0":
        problem(f"{path}: cff-version must be the string 1.2.0, not {cff.get('cff-version')!r}")
    for key in ("message", "title", "abstract"):
        if key in cff and not nonempty_string(cff[key]):
            problem(f"{path}: {key} must be a non-empty string")
    if cff.get("type", "software") not in ("software", "dataset"):
        problem(f"{path}: type must be software or dataset")
    check_authors(path, cff.get("authors"))
    check_common(path, cff)
    refs = cff.get("references", [])
    if not isinstance(refs, list) or not refs:
        problem(f"{path}: references must be a non-empty list")
        refs = []
    for i, ref in enumerate(refs):
        where = f"{path}: reference {i + 1}"
        if not isinstance(ref, dict):
            problem(f"{where}: must be a mapping")
            continue
        if REFERENCE_REQUIRED - set(ref):
            problem(f"{where}: required keys missing: {sorted(REFERENCE_REQUIRED - set(ref))}")
        if set(ref) - REFERENCE_KEYS:
            problem(f"{where}: keys CFF 1.2.0 does not define: {sorted(set(ref) - REFERENCE_KEYS)}")
        for key in REFERENCE_INTEGERS & set(ref):
            if not isinstance(ref[key], int) or isinstance(ref[key], bool):
                problem(f"{where}: {key} must be an integer, not {ref[key]!r}")
        check_authors(where, ref.get("authors"))
        check_common(where, ref)
    paper = [r for r in refs if isinstance(r, dict) and r.get("doi") == "10.1103/PhysRevLett.112.038001"]
    if len(paper) != 1:
        problem(f"{path}: no reference to the paper reproduced (doi 10.1103/PhysRevLett.112.038001)")
    else:
        p = paper[0]
        names = [a.get("family-names") for a in p.get("authors", [])]
        expected = (["Pathak", "Jabeen", "Das", "Rajesh"], "Physical Review Letters", 112, 2014,
                    "Energy decay in three-dimensional freely cooling granular gas")
        if (names, p.get("journal"), p.get("volume"), p.get("year"), p.get("title")) != expected:
            problem(f"{path}: the paper's reference is not Pathak, Jabeen, Das, Rajesh, PRL 112 (2014): {p}")
    if shutil.which("cffconvert"):
        r = subprocess.run(["cffconvert", "--validate", "-i", path], capture_output=True, text=True)
        if r.returncode != 0:
            problem(f"{path}: cffconvert --validate: {r.stdout}{r.stderr}")
    return cff


def main():
    source = sys.argv[1]
    cmake = open(os.path.join(source, "CMakeLists.txt"), encoding="utf-8").read()
    m = re.search(r"project\(\s*coolgas\s+VERSION\s+([0-9][0-9.]*)", cmake)
    if not m:
        problem("CMakeLists.txt: no project(coolgas VERSION x.y.z)")
        return 1
    version = m.group(1)
    print(f"CMakeLists.txt: version {version}")

    news = open(os.path.join(source, "NEWS.md"), encoding="utf-8").read()
    top = re.search(r"^## (\S+)", news, re.MULTILINE)
    if not top or top.group(1) != version:
        problem(f"NEWS.md: the top entry is {top.group(1) if top else 'missing'}, the project's version {version}")

    cff = check_citation(os.path.join(source, "CITATION.cff"))
    if cff is not None:
        if str(cff.get("version")) != version:
            problem(f"CITATION.cff: version {cff.get('version')!r}, the project's {version}")
        if cff.get("license") != "GPL-3.0-or-later":
            problem(f"CITATION.cff: license {cff.get('license')!r}, not GPL-3.0-or-later")

    licence = open(os.path.join(source, "LICENSE"), encoding="utf-8").read()
    if "GNU GENERAL PUBLIC LICENSE" not in licence or "Version 3, 29 June 2007" not in licence:
        problem("LICENSE: not the text of the GNU GPL, version 3")
    readme = open(os.path.join(source, "README.md"), encoding="utf-8").read()
    if "GPL-3.0-or-later" not in readme:
        problem("README.md: does not name the licence GPL-3.0-or-later")

    print(f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
