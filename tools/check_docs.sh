#!/usr/bin/env bash
# The pages describe the product as it is; its history is the git log. Fails when
#   - README.md has more than 200 lines, or
#   - a Markdown page of the tree (README.md, docs/, plc_bindings/, examples/, …; not build/,
#     target/ or .git/) names an issue ("issue 13", "issues 4", "#13"), a work session
#     ("the previous session", "seventh session") or the date of an experiment (2026-11-27).
#     CHANGELOG.md is the one page that is history by design (release dates): it is not read.
# PLC literals (T#0, 16#FF, WORD#16#0003) and FSoE's "Session" frames are not matches.
#   bash tools/check_docs.sh             the repository
#   bash tools/check_docs.sh DIR         another tree (the self-test's)
#   bash tools/check_docs.sh --selftest  shows that each rule fails on a tree that breaks it
#                                        and that a clean tree with PLC literals passes
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
max_readme=200

# one extended regex per rule, matched line by line
rules=(
    '[Ii][Ss][Ss][Uu][Ee][Ss]? ?#?[0-9]+'
    '(^|[^[:alnum:]#_&/;:.-])#[0-9]+([^[:alnum:]_-]|$)'
    '(^|[^[:alnum:]])([Tt]his|[Tt]hat|[Pp]revious|[Ll]ast|[Ee]arlier|[Ll]ater|[Nn]ext|[Ff]irst|[Ss]econd|[Tt]hird|[Ff]ourth|[Ff]ifth|[Ss]ixth|[Ss]eventh|[Ee]ighth|[Nn]inth|[Tt]enth|[Ss]ame|[Oo]ne) sessions?([^[:alnum:]]|$)'
    '(^|[^[:alnum:]])sessions? by sessions?([^[:alnum:]]|$)'
    '(^|[^[:alnum:]])20[0-9][0-9]-[01][0-9]-[0-3][0-9]([^[:alnum:]]|$)'
)

check_tree() {
    local root=$1 bad=0 n f hits
    hits=$(mktemp)
    n=$(wc -l <"$root/README.md")
    if [ "$n" -gt "$max_readme" ]; then
        echo "FAIL: README.md has $n lines, at most $max_readme (move the rest to docs/)"
        bad=1
    fi
    while IFS= read -r f; do
        for r in "${rules[@]}"; do
            if grep -nE "$r" "$f" >"$hits"; then
                sed "s|^|FAIL: ${f#"$root"/}:|" "$hits" | cut -c1-220
                bad=1
            fi
        done
    done < <(find "$root" \( -name .git -o -name target -o -name build \) -prune -o -name '*.md' ! -path "$root/CHANGELOG.md" -type f -print | sort)
    rm -f "$hits"
    return $bad
}

if [ "${1:-}" = --selftest ]; then
    t=$(mktemp -d)
    trap 'rm -rf "$t"' EXIT
    mkdir -p "$t/docs"
    clean='The timer fires at T#0, the mask is 16#FF or WORD#16#0003; a Session frame, the first Session frame; #include <stdio.h>; see [abi](#5-status-codes).'
    fails=0
    case_() { # name, README lines, page text: expect fail unless name is "clean"
        local name=$1 lines=$2 text=$3
        rm -rf "$t/docs"/* && seq "$lines" >"$t/README.md" && printf '%s\n' "$clean" "$text" >"$t/docs/page.md"
        if check_tree "$t" >"$t/log" 2>&1; then got=pass; else got=fail; fi
        want=fail; [ "$name" = clean ] && want=pass
        if [ "$got" = "$want" ]; then
            echo "selftest $name: $got, as it must"
        else
            echo "selftest $name: $got, expected $want"; cat "$t/log"; fails=1
        fi
    }
    case_ clean 200 'Nothing here but the product.'
    case_ readme-201-lines 201 'Nothing here but the product.'
    case_ issue-number 10 'as issue 13 asks'
    case_ hash-number 10 'fixed in #13.'
    case_ previous-session 10 'the previous session made it faster'
    case_ numbered-session 10 'measured again (seventh session)'
    case_ date 10 'measured on 2026-11-27, AMD VM'
    exit $fails
fi

root=${1:-$(cd "$here/.." && pwd)}
if check_tree "$root"; then
    echo "check_docs: README.md $(wc -l <"$root/README.md") lines (at most $max_readme); no issue numbers, sessions or experiment dates in $(find "$root" \( -name .git -o -name target -o -name build \) -prune -o -name '*.md' -type f -print | wc -l) Markdown pages"
else
    exit 1
fi
