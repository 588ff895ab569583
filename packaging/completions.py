#!/usr/bin/env python3
"""Writes bash, zsh and fish completion for lancer from the built program's own --help.

Run at build time (packaging/CMakeLists.txt): `completions.py LANCER OUT_DIR` writes OUT_DIR/bash/lancer,
OUT_DIR/zsh/_lancer and OUT_DIR/fish/lancer.fish. Generated rather than written by hand so that a new
option, choice or subcommand is completed as soon as the program has it; tests/install/completion_test.sh
checks the result against --help by asking each shell.

The help text is CLI11's: section headings ("Options:", "Camera:", "Subcommands:") at column 0, then one
entry per line at column 2: the names and value type ("-o,--output TEXT", "--look TEXT:{studio,sky,sun}",
"--clip TEXT ...", "--srgb Excludes: --linear"), two or more spaces, and the description, which moves
to the next, deeper-indented line when the left column is too wide.
"""
import re
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path


@dataclass
class Option:
    names: list  # "-o", "--output"
    description: str = ""
    value: str = ""  # the value's type ("TEXT", "INT", "SIZE", "X,Y,Z"); "" for a flag
    choices: list = field(default_factory=list)
    repeats: bool = False

    @property
    def wants_file(self):
        # Files where the option names one (-o,--output, --legend-file, --gmsh-view's options file);
        # other text values (a field, an axis, a range) have nothing to offer.
        named = re.search(r"output|file", " ".join(self.names)) or re.search(r"\bfile\b", self.description, re.I)
        return self.value in ("TEXT", "FILE") and not self.choices and named is not None


@dataclass
class Command:
    name: str
    description: str = ""
    options: list = field(default_factory=list)
    takes_files: bool = False  # has positionals: the input files


def parse_option(left):
    words = left.split(" ")
    option = Option(names=words[0].split(","))
    rest = words[1:]
    if rest and not re.fullmatch(r"(Excludes|Needs):|REQUIRED", rest[0]):
        option.value = rest[0].split(":")[0].split("=")[0]
        choices = re.search(r"\{([^}]*)\}", rest[0])
        if choices:
            option.choices = choices.group(1).split(",")
    option.repeats = "..." in rest
    return option


def parse_help(text, name):
    """The options, positionals and subcommands of one --help text."""
    command = Command(name)
    subcommands = []
    section = ""
    last = None  # the entry whose description may be on the next line
    for line in text.splitlines():
        heading = re.fullmatch(r"(\S.*):", line)
        if heading:
            section, last = heading.group(1), None
            continue
        entry = re.fullmatch(r"  (\S.*?)(?: {2,}(.*))?", line)
        if entry:
            left, description = entry.group(1), entry.group(2) or ""
            if section == "Subcommands":
                last = Command(left, description)
                subcommands.append(last)
            elif section == "Positionals":
                command.takes_files, last = True, None
            elif left.startswith("-"):
                last = parse_option(left)
                last.description = description
                command.options.append(last)
            continue
        continuation = re.fullmatch(r" {3,}(\S.*)", line)
        if continuation and last is not None and not last.description:
            last.description = continuation.group(1)
    return command, subcommands


def run_help(lancer, *words):
    return subprocess.run([lancer, *words, "--help"], check=True, capture_output=True, text=True).stdout


def summary(description):
    """The description up to its first "; " or ": " outside parentheses, short enough for a menu."""
    depth = 0
    for i, character in enumerate(description):
        depth += {"(": 1, ")": -1}.get(character, 0)
        if depth == 0 and description[i:i + 2] in ("; ", ": "):
            return description[:i]
    return description


def long_names(option):
    return [n for n in option.names if n.startswith("--")]


def words_of(options):
    return " ".join(n for o in options for n in o.names)


def bash_script(top, commands):
    global_value_options = [n for o in top.options if o.value for n in o.names]
    lines = [
        "# bash completion for lancer, generated from `lancer --help` by packaging/completions.py",
        "_lancer() {",
        '  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]} command="" i',
        "  # The subcommand: the first word that is neither an option nor a global option's value.",
        "  for ((i = 1; i < COMP_CWORD; i++)); do",
        '    case ${COMP_WORDS[i]} in',
    ]
    if global_value_options:
        lines.append(f"      {'|'.join(global_value_options)}) ((i++)) ;;")
    lines += [
        "      -*) ;;",
        "      *) command=${COMP_WORDS[i]}; break ;;",
        "    esac",
        "  done",
        '  case "$command:$prev" in',
    ]
    for command in [top, *commands]:
        scope = command.name if command is not top else ""
        for option in command.options + (top.options if command is not top else []):
            if not option.value:
                continue
            patterns = "|".join(f'"{scope}:{n}"' for n in option.names)
            if option.choices:
                action = f'COMPREPLY=($(compgen -W "{" ".join(option.choices)}" -- "$cur")); return'
            elif option.wants_file:
                action = 'compopt -o filenames; COMPREPLY=($(compgen -f -- "$cur")); return'
            else:
                action = "COMPREPLY=(); return"  # a number, a size, a point: nothing to offer
            lines.append(f"    {patterns}) {action} ;;")
    lines += ["  esac", '  case "$command" in']
    top_words = words_of(top.options)
    lines.append(f'    "") if [[ $cur == -* ]]; then COMPREPLY=($(compgen -W "{top_words}" -- "$cur")); '
                 f'else COMPREPLY=($(compgen -W "{" ".join(c.name for c in commands)}" -- "$cur")); fi ;;')
    for command in commands:
        options = command.options + [o for o in top.options if "--help" not in o.names and "--version" not in o.names]
        files = 'compopt -o filenames; COMPREPLY=($(compgen -f -- "$cur"))' if command.takes_files else "COMPREPLY=()"
        lines.append(f'    {command.name}) if [[ $cur == -* ]]; then COMPREPLY=($(compgen -W "{words_of(options)}" '
                     f'-- "$cur")); else {files}; fi ;;')
    lines += ["  esac", "}", "complete -F _lancer lancer", ""]
    return "\n".join(lines)


def zsh_quote(text):
    return "'" + text.replace("'", "'\\''") + "'"


def zsh_spec(option):
    description = summary(option.description).replace("\\", "\\\\").replace("[", "\\[").replace("]", "\\]")
    if option.value:
        action = f"({' '.join(option.choices)})" if option.choices else ("_files" if option.wants_file else " ")
        tail = f":{option.value.replace(':', '')}:{action}"
    else:
        tail = ""
    exclusive = f"({' '.join(option.names)})" if len(option.names) > 1 else ""
    repeat = "*" if option.repeats else ""
    return [zsh_quote(f"{exclusive}{repeat}{name}[{description}]{tail}") for name in option.names]


def zsh_script(top, commands):
    global_options = [o for o in top.options if "--help" not in o.names and "--version" not in o.names]
    lines = [
        "#compdef lancer",
        "# zsh completion for lancer, generated from `lancer --help` by packaging/completions.py",
        "_lancer() {",
        "  local curcontext=$curcontext state line ret=1",
        "  typeset -A opt_args",
        "  _arguments -C \\",
    ]
    lines += [f"    {spec} \\" for o in top.options for spec in zsh_spec(o)]
    lines += ["    '1: :->command' \\", "    '*:: :->arguments' && ret=0", "  case $state in", "    command)",
              "      local -a commands=("]
    lines += [f"        {zsh_quote(c.name + ':' + summary(c.description))}" for c in commands]
    lines += ["      )", "      _describe -t commands 'lancer command' commands && ret=0 ;;", "    arguments)",
              "      curcontext=${curcontext%:*:*}:lancer-$line[1]:", "      case $line[1] in"]
    for command in commands:
        lines.append(f"        {command.name})")
        lines.append("          _arguments \\")
        lines += [f"            {spec} \\" for o in command.options + global_options for spec in zsh_spec(o)]
        lines.append("            '*:file:_files' && ret=0 ;;" if command.takes_files else "            && ret=0 ;;")
    lines += ["      esac ;;", "  esac", "  return ret", "}", '_lancer "$@"', ""]
    return "\n".join(lines)


def fish_quote(text):
    return "'" + text.replace("\\", "\\\\").replace("'", "\\'") + "'"


def fish_line(condition, option):
    parts = ["complete -c lancer"]
    if condition:
        parts.append(f"-n {fish_quote(condition)}")
    for name in option.names:
        parts.append(f"-l {name[2:]}" if name.startswith("--") else f"-s {name[1:]}")
    if option.value:
        if option.choices:
            parts.append(f"-x -a {fish_quote(' '.join(option.choices))}")
        elif option.wants_file:
            parts.append("-r -F")
        else:
            parts.append("-x")
    parts.append(f"-d {fish_quote(summary(option.description))}")
    return " ".join(parts)


def fish_script(top, commands):
    lines = ["# fish completion for lancer, generated from `lancer --help` by packaging/completions.py",
             "complete -c lancer -f"]
    for option in top.options:
        # Global options (fallthrough): before and after the subcommand; --version only before.
        condition = "__fish_use_subcommand" if "--version" in option.names else ""
        lines.append(fish_line(condition, option))
    for command in commands:
        lines.append(f"complete -c lancer -n '__fish_use_subcommand' -a {command.name} "
                     f"-d {fish_quote(summary(command.description))}")
    for command in commands:
        condition = f"__fish_seen_subcommand_from {command.name}"
        for option in command.options:
            if "--help" in option.names:
                continue  # the global -h,--help already covers it
            lines.append(fish_line(condition, option))
        if command.takes_files:
            lines.append(f"complete -c lancer -n {fish_quote(condition)} -F")
    lines.append("")
    return "\n".join(lines)


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: completions.py LANCER OUT_DIR")
    lancer, out = sys.argv[1], Path(sys.argv[2])
    top, commands = parse_help(run_help(lancer), "")
    if not commands:
        sys.exit(f"completions.py: `{lancer} --help` lists no subcommands")
    for command in commands:
        parsed, _ = parse_help(run_help(lancer, command.name), command.name)
        command.options, command.takes_files = parsed.options, parsed.takes_files
    for relative, text in (("bash/lancer", bash_script(top, commands)), ("zsh/_lancer", zsh_script(top, commands)),
                           ("fish/lancer.fish", fish_script(top, commands))):
        path = out / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)


if __name__ == "__main__":
    main()
