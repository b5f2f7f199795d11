# bash completion for apcs (installed as share/bash-completion/completions/apcs).
# Stands alone: it needs neither the bash-completion package nor its helpers. Each command takes
# only its own options: the lists below are those of `apcs COMMAND --help` (tests/e2e/completion.sh
# compares them).

# The words of "$1" that start with "$2".
_apcs_words()
{
    mapfile -t COMPREPLY < <(compgen -W "$1" -- "$2")
}

# The files ending in ".$1" that start with "$2", and folders, so that a file further down can be
# reached.
_apcs_files()
{
    mapfile -t COMPREPLY < <(compgen -d -- "$2"; compgen -f -X "!*.$1" -- "$2")
}

_apcs_options()
{
    local staff="--tension --continuity --bias --accel"
    local curve="--slopes --samples --spacing --inbetweens"
    local view="--theta --phi --view"
    local pictures="--png --png-raw --svg"
    local terminal_pictures="--sixel --kitty"
    case $1 in
        path) echo "$staff $curve $view $pictures $terminal_pictures --print --sif-param --help" ;;
        export) echo "$staff $curve --surface $view --sif --sif-motion --frames-per-span --fps --help" ;;
        fit) echo "$staff $curve --surface $view $pictures $terminal_pictures --gif --delay --print --out --help" ;;
        inbetween) echo "--inbetweens --frames --law --pad $view $pictures $terminal_pictures --gif --delay --print --out --help" ;;
        draw) echo "$view $pictures $terminal_pictures --help" ;;
        play) echo "$staff --slopes --samples --spacing --surface $view --glyphs --pixels $pictures $terminal_pictures --gif --delay --print --out --tree --help" ;;
        figures) echo "$staff $curve --workdir --out --paper --help" ;;
        *) echo "$staff $curve --surface $view --delay --glyphs --color --pixels --step $pictures --workdir --keys --pace --record --handout --paper --help --version" ;;
    esac
}

_apcs()
{
    local current=${COMP_WORDS[COMP_CWORD]}
    local previous=${COMP_WORDS[COMP_CWORD - 1]}
    COMPREPLY=()

    case $previous in
        --glyphs) _apcs_words "ascii braille blocks" "$current"; return ;;
        --color) _apcs_words "auto always never" "$current"; return ;;
        --pixels) _apcs_words "auto sixel kitty off" "$current"; return ;;
        --spacing) _apcs_words "nearest exact" "$current"; return ;;
        --surface) _apcs_words "blend ferguson" "$current"; return ;;
        --view) _apcs_words "front side top" "$current"; return ;;
        --sif-motion) _apcs_words "tcb frames" "$current"; return ;;
        --sif) _apcs_files sif "$current"; return ;;
        --pace) _apcs_words "step 500 1000 2000" "$current"; return ;;
        --law) _apcs_words "linear sqrt square ease-in ease-out ease-in-out" "$current"; return ;;
        --pad) _apcs_words "apcs start end middle midpoint" "$current"; return ;;
        --keys | --record) _apcs_files keys "$current"; return ;;
        --png | --png-raw) _apcs_files png "$current"; return ;;
        --svg) _apcs_files svg "$current"; return ;;
        --gif) _apcs_files gif "$current"; return ;;
        --sixel) _apcs_files six "$current"; return ;;
        --kitty) _apcs_files kitty "$current"; return ;;
        --out | --workdir | --handout) mapfile -t COMPREPLY < <(compgen -d -- "$current"); return ;;
        --tension | --continuity | --bias | --accel | --slopes | --samples | --inbetweens | --theta | \
            --phi | --delay | --step | --frames | --frames-per-span | --fps | --sif-param) return ;;
    esac

    local command="" word
    for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do
        case $word in path | inbetween | fit | export | draw | play | figures) command=$word; break ;; esac
    done

    if [[ $current == -* ]]; then
        _apcs_words "$(_apcs_options "$command")" "$current"
    elif [[ -z $command ]]; then
        _apcs_words "path inbetween fit export draw play figures" "$current"
    elif [[ $command == play ]]; then
        _apcs_files scn "$current"
    elif [[ $command == path ]]; then
        # A path file, or a Synfig document read as one.
        mapfile -t COMPREPLY < <(compgen -d -- "$current"; compgen -f -X '!*.dat' -- "$current"
                                 compgen -f -X '!*.sif' -- "$current")
    elif [[ $command != figures ]]; then
        _apcs_files dat "$current"
    fi
}

complete -o filenames -F _apcs apcs
