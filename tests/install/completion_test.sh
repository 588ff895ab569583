#!/usr/bin/env bash
# The man pages and the bash/zsh/fish completion of a build (packaging/) against the program's own
# --help: every subcommand has its page and is completed; every option of every subcommand is on its
# page and is offered by each shell; every option with a fixed set of values completes to that set.
# The options are read from --help here with a plain pattern, independently of packaging/completions.py.
# bash is asked for real (its completion function); zsh and fish, when installed, check the syntax and
# fish is asked too (`complete -C`); without them their files are read.
# Usage: completion_test.sh BUILD_DIR
set -euo pipefail
build=$1
lancer=$build/lancer
completion=$build/packaging/completion
man=$build/packaging/man

fail() {
  echo "completion_test: $*" >&2
  exit 1
}
for file in "$completion/bash/lancer" "$completion/zsh/_lancer" "$completion/fish/lancer.fish" "$man/lancer.1"; do
  [ -f "$file" ] || fail "no $file (built by the programs target)"
done

# Subcommands: the first word of each line of --help's "Subcommands:" section.
mapfile -t commands < <("$lancer" --help | awk '/^Subcommands:/ {on = 1; next} /^[^ ]/ {on = 0} on && /^  [a-z]/ {print $1}')
((${#commands[@]} >= 5)) || fail "lancer --help lists ${#commands[@]} subcommands: ${commands[*]}"
# A subcommand's options: every name in the left column of its --help ("-o,--output TEXT" gives -o, --output).
options_of() {
  "$lancer" "$1" --help | grep -E '^  -' | awk '{print $1}' | tr ',' '\n'
}
# The values of each option with a fixed set: "--look studio sky sun".
choices_of() {
  "$lancer" "$1" --help | sed -nE 's/^  (-[a-zA-Z],)?(--[a-z0-9-]+) [A-Z]+:\{([^}]*)\}.*/\2 \3/p' | tr ',' ' '
}

# bash: what _lancer puts in COMPREPLY for a command line whose last word is being completed.
bash_complete() {
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _lancer 2>/dev/null
           printf "%s\n" "${COMPREPLY[@]}"' _ "$completion/bash/lancer" "$@"
}
offered=$(bash_complete lancer "")
for command in "${commands[@]}"; do
  grep -qx -- "$command" <<<"$offered" || fail "bash does not offer the subcommand $command (offers: $offered)"
done
grep -qx -- --max-memory <<<"$(bash_complete lancer --)" || fail "bash does not offer lancer --max-memory"

have_zsh=$(command -v zsh || true)
have_fish=$(command -v fish || true)
[ -z "$have_zsh" ] || zsh -n "$completion/zsh/_lancer" || fail "zsh: syntax error in $completion/zsh/_lancer"
[ -z "$have_fish" ] || fish -n "$completion/fish/lancer.fish" || fail "fish: syntax error in $completion/fish/lancer.fish"
checked=0
for command in "${commands[@]}"; do
  page=$man/lancer-$command.1
  [ -f "$page" ] || fail "no man page $page for lancer $command"
  grep -q "^\.TH LANCER-${command^^} " "$page" || fail "$page is not titled LANCER-${command^^}"
  bash_options=$(bash_complete lancer "$command" -)
  fish_options=""
  if [ -n "$have_fish" ]; then
    fish_options=$(fish --no-config -c "source '$completion/fish/lancer.fish'; complete -C 'lancer $command -'" | cut -f1)
  fi
  while read -r option; do
    grep -qx -- "$option" <<<"$bash_options" || fail "bash does not offer lancer $command $option"
    grep -qF -- "${option//-/\\-}" "$page" || fail "$page does not describe $option"
    grep -qF -- "${option}[" "$completion/zsh/_lancer" || fail "zsh completion has no lancer $command $option"
    if [ -n "$have_fish" ]; then
      grep -qx -- "$option" <<<"$fish_options" || fail "fish does not offer lancer $command $option"
    elif [[ $option == --* ]]; then
      grep -qE -- "__fish_seen_subcommand_from $command'.* -l ${option#--}( |$)" "$completion/fish/lancer.fish" ||
        [ "$option" = --help ] || fail "fish completion has no lancer $command $option"
    fi
    checked=$((checked + 1))
  done < <(options_of "$command")
  while read -r option values; do
    [ -n "$option" ] || continue
    offered=$(bash_complete lancer "$command" "$option" "" | sort | tr '\n' ' ')
    expected=$(tr ' ' '\n' <<<"$values" | sort | tr '\n' ' ')
    [ "$offered" = "$expected" ] || fail "bash offers '$offered' after lancer $command $option, --help says '$expected'"
  done < <(choices_of "$command")
done
fish_check=read
[ -z "$have_fish" ] || fish_check=asked
echo "completion_test: ${#commands[@]} subcommands, $checked options: bash asked, zsh ${have_zsh:+syntax-checked and }read," \
  "fish $fish_check, the man pages read"
