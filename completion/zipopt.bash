# bash completion for zipopt: the commands, each command's options, scene files (*.ini),
# folders for --out and the search strategies for --algorithm (asked of zipopt itself).

# appends the lines read (names with spaces stay whole) to COMPREPLY
_zipopt_add() {
    local line
    while IFS= read -r line; do
        COMPREPLY+=("$line")
    done
}

_zipopt() {
    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}
    local cmd='' study='' i
    for ((i = 1; i < COMP_CWORD; i++)); do
        case ${COMP_WORDS[i]} in
        simulate | check | landscape | tradeoff | sweep | bench) [[ -z $cmd ]] && cmd=${COMP_WORDS[i]} ;;
        trade) [[ $cmd == bench ]] && study=trade ;;
        esac
    done

    case $prev in
    --out)
        _zipopt_add < <(compgen -d -- "$cur")
        return
        ;;
    --schedule)
        _zipopt_add < <(compgen -f -X '!*.ini' -- "$cur")
        _zipopt_add < <(compgen -d -- "$cur")
        return
        ;;
    --algorithm)
        local algos
        algos=$("${COMP_WORDS[0]}" --help-all 2>/dev/null |
            sed -n '/^strategies:/,/^$/s/^  \([a-z0-9-]*\) .*/\1/p')
        _zipopt_add < <(compgen -W "$algos" -- "$cur")
        return
        ;;
    --run)
        _zipopt_add < <(compgen -W "search simulate" -- "$cur")
        return
        ;;
    --force | --vary | --seed | --max-evals | --max-time | --sample-times | --frames-at | --fps | --size | \
        --speedup | --force-range | --slice | --range | --repeats | --levels | --power)
        return # a value the user types
        ;;
    esac
    local opts
    case $cmd in
    simulate) opts="--force --schedule --json --sample-times --gradient --out --plot --frames-at --animate
                    --fps --size --speedup --help" ;;
    check) opts="--json --plot --out --help" ;;
    landscape) opts="--force-range --slice --range --force --schedule --out --json --help" ;;
    sweep) opts="--vary --run --out --resume --json --grid-schedule --no-grid-schedule --max-evals
                 --max-time --schedule --force --help" ;;
    bench) opts="--repeats --json --out --help" ;;
    tradeoff) opts="--levels --power --max-evals --max-time --schedule --force --json --out --help" ;;
    *) opts="--out --algorithm --seed --max-evals --max-time --no-plot --json --help --help-all
             --version" ;;
    esac
    if [[ $cur == -* ]]; then
        _zipopt_add < <(compgen -W "$opts" -- "$cur")
    elif [[ $cmd == bench && -z $study ]]; then
        _zipopt_add < <(compgen -W "trade" -- "$cur")
    else
        _zipopt_add < <(compgen -f -X '!*.ini' -- "$cur")
        _zipopt_add < <(compgen -d -- "$cur")
        if [[ -z $cmd && $COMP_CWORD == 1 ]]; then
            _zipopt_add < <(compgen -W "simulate check landscape tradeoff sweep bench" -- "$cur")
        fi
    fi
}
complete -o filenames -F _zipopt zipopt
