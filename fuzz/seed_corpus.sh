#!/usr/bin/env bash
# Seeds fuzz/corpus/ from the real profile files and the scene of tests/fuzz.rs.
# profile_text: one input per file and selector byte (format + 3 kind + 6 StepBack::Drop +
# 12 smoothing), see fuzz_targets/profile_text.rs.
set -euo pipefail
cd "$(dirname "$0")"
mkdir -p corpus/profile_text corpus/scene_toml
for path in ../tests/data/profiles/* ../tests/data/profiles/bad/*; do
    name=$(basename "$path")
    case "${name##*.}" in
        csv) format=0; kind=1 ;;
        prw|PRW) format=1; kind=0 ;;
        prr|PRR) format=1; kind=1 ;;
        whl|WHL) format=2; kind=0 ;;
        ban|BAN) format=2; kind=1 ;;
        *) continue ;;
    esac
    for option in 0 1; do
        for smoothing in 0 1; do
            selector=$((format + 3 * kind + 6 * option + 12 * smoothing))
            { printf "\\$(printf '%03o' "$selector")"; cat "$path"; } \
                > "corpus/profile_text/$name.$option$smoothing"
        done
    done
done
sed -n '/^const VALID_SCENE: &str = r#"/,/^"#;/p' ../tests/fuzz.rs | sed '1s/^.*r#"//; $d' \
    > corpus/scene_toml/full.toml
: > corpus/scene_toml/empty.toml
