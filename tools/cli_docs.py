#!/usr/bin/env python3
"""The man pages and bash completions of both programs, from their own --help.

    tools/cli_docs.py man-cli PROBECYCLE_CLI VERSION OUT.1
    tools/cli_docs.py man-window PROBECYCLE VERSION OUT.1
    tools/cli_docs.py completion PROBECYCLE_CLI PROBECYCLE OUT

Every command, option and word comes from running the programs (the CLI's
CLI11 help, the window's QCommandLineParser help), so the pages and the
completion cannot drift from them; the build runs this after linking both
(app/CMakeLists.txt). The window runs with QT_QPA_PLATFORM=offscreen.
"""
import datetime
import gzip
import io
import os
import re
import subprocess
import sys


def run_help(program, args):
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
    done = subprocess.run([program] + args, capture_output=True, text=True, env=env, check=True)
    return done.stdout


def section(text, title):
    """The lines of a --help section ("Options:", "Subcommands:")."""
    lines = []
    inside = False
    for line in text.splitlines():
        if line.rstrip() == title:
            inside = True
            continue
        if inside:
            if line and not line.startswith(" "):
                break
            lines.append(line)
    return lines


def subcommands(text):
    """(name, description) of each line of the Subcommands: section."""
    out = []
    for line in section(text, "Subcommands:"):
        m = re.match(r"^  (\S+)\s+(.*)$", line)
        if m:
            out.append((m.group(1), m.group(2)))
    return out


def options(text):
    """{option: [words]} of the Options: section; words from a type like a|b|c."""
    out = {}
    for line in section(text, "Options:"):
        m = re.match(r"^  (-\S+)(?:\s+(\S+))?", line)
        if not m:
            continue
        names = [n for n in m.group(1).split(",") if n.startswith("--")]
        words = []
        if m.group(2) and "|" in m.group(2) and not m.group(2).startswith("-"):
            words = [w for w in m.group(2).split("|") if re.fullmatch(r"[A-Za-z0-9_+-]+", w)]
        for name in names:
            out[name] = words
    return out


def command_tree(cli):
    """[(path, help text)] for the CLI and every command and verb."""
    top = run_help(cli, ["--help"])
    tree = [([], top)]
    for name, _ in subcommands(top):
        text = run_help(cli, [name, "--help"])
        tree.append(([name], text))
        for verb, _ in subcommands(text):
            tree.append(([name, verb], run_help(cli, [name, verb, "--help"])))
    return tree


def roff(text):
    """Text safe in a .nf block: backslashes doubled, a leading . or ' escaped."""
    out = []
    for line in text.splitlines():
        line = line.replace("\\", "\\e")
        if line.startswith(".") or line.startswith("'"):
            line = "\\&" + line
        out.append(line)
    return "\n".join(out)


def date():
    epoch = os.environ.get("SOURCE_DATE_EPOCH")
    when = (datetime.datetime.fromtimestamp(int(epoch), datetime.timezone.utc)
            if epoch else datetime.datetime.now(datetime.timezone.utc))
    return when.strftime("%Y-%m-%d")


def man_cli(cli, version, out):
    tree = command_tree(cli)
    top = tree[0][1]
    summary = top.splitlines()[0].split(": ", 1)[-1].rstrip(".")
    page = [f'.TH PROBECYCLE-CLI 1 "{date()}" "ProbeCycle {version}" "User Commands"',
            ".SH NAME", f"probecycle-cli \\- {roff(summary)}",
            ".SH SYNOPSIS", ".B probecycle-cli", ".I COMMAND", "[\\fIOPTIONS\\fR]",
            ".br", ".B probecycle-cli", ".I COMMAND", "\\fB--help\\fR",
            ".br", ".B probecycle-cli", "\\fB--version\\fR",
            ".SH DESCRIPTION", ".nf", roff(top), ".fi", ".SH COMMANDS"]
    for path, text in tree[1:]:
        page += [".SS " + " ".join(path), ".nf", roff(text), ".fi"]
    page += [".SH EXIT STATUS", "0 on success, 2 on bad input or usage (the message on stderr).",
             ".SH SEE ALSO", ".BR probecycle (1)",
             ".PP", "The documentation in /usr/share/doc/probecycle."]
    write(out, "\n".join(page) + "\n")


def man_window(window, version, out):
    # The usage line names the program as it was run: the build's path.
    text = re.sub(r"^Usage: \S+", "Usage: probecycle", run_help(window, ["--help"]), flags=re.M)
    summary = text.splitlines()[1].rstrip(".")
    summary = summary[:1].lower() + summary[1:]
    page = [f'.TH PROBECYCLE 1 "{date()}" "ProbeCycle {version}" "User Commands"',
            ".SH NAME", f"probecycle \\- {roff(summary)}",
            ".SH SYNOPSIS", ".B probecycle", "[\\fIOPTIONS\\fR] [\\fISCENARIO.json\\fR|\\fIPROJECT.probecycle\\fR]",
            ".SH DESCRIPTION",
            "The window: parameters with sliders, the cycle's charts and warnings, the "
            "calibration and latency lab, comparison measurement and the optimiser. Without a "
            "display, run it with QT_QPA_PLATFORM=offscreen and --screenshot or --report-pdf.",
            ".SH OPTIONS", ".nf", roff(text), ".fi",
            ".SH SEE ALSO", ".BR probecycle-cli (1)"]
    write(out, "\n".join(page) + "\n")


def completion(cli, window, out):
    tree = command_tree(cli)
    cases = []
    for path, text in tree:
        subs = [name for name, _ in subcommands(text)]
        opts = options(text)
        key = " ".join(path)
        words = " ".join(subs + sorted(opts))
        values = [f'            {name}) COMPREPLY=($(compgen -W "{" ".join(w)}" -- "$cur")); return ;;'
                  for name, w in sorted(opts.items()) if w]
        cases.append(f'        "{key}")\n            case "$prev" in\n' +
                     ("\n".join(values) + "\n" if values else "") +
                     f'            esac\n            COMPREPLY=($(compgen -W "{words}" -- "$cur"))\n'
                     f'            [ ${{#COMPREPLY[@]}} -eq 0 ] && COMPREPLY=($(compgen -f -- "$cur"))\n'
                     "            ;;")
    window_help = run_help(window, ["--help"])
    window_opts = sorted(set(re.findall(r"(--[a-z][a-z0-9-]*)", "\n".join(
        line for line in window_help.splitlines() if line.startswith("  -")))))
    # The window's words: its own help names them ("cycle (default), calibration, ...").
    tabs = re.search(r"--tab <NAME>\s+Tab for[^:]*:\s*(.*?)\.\n\s*(?:\n|  -)", window_help, re.S)
    tab_words = re.findall(r"[a-z]+", re.sub(r"\(default\)|\bor\b", "", tabs.group(1))) if tabs else []
    languages = re.search(r"--language <CODE>\s+Interface language:\s*([^.\n]*)", window_help)
    language_words = re.findall(r"[A-Za-z_]+", re.sub(r"\bor\b", "", languages.group(1))) if languages else []
    script = f"""# bash completion for probecycle-cli and probecycle, generated by
# tools/cli_docs.py from the programs' own --help: do not edit.

_probecycle_cli() {{
    local cur prev path word i
    cur="${{COMP_WORDS[COMP_CWORD]}}"
    prev="${{COMP_WORDS[COMP_CWORD-1]}}"
    path=""
    for ((i = 1; i < COMP_CWORD; i++)); do
        word="${{COMP_WORDS[i]}}"
        case "$word" in -*) continue ;; esac
        case "${{path:+$path }}$word" in
{chr(10).join(f'            "{" ".join(p)}") path="{" ".join(p)}" ;;' for p, _ in tree[1:])}
        esac
    done
    case "$path" in
{chr(10).join(cases)}
    esac
}}
complete -F _probecycle_cli probecycle-cli

_probecycle() {{
    local cur prev
    cur="${{COMP_WORDS[COMP_CWORD]}}"
    prev="${{COMP_WORDS[COMP_CWORD-1]}}"
    case "$prev" in
        --tab) COMPREPLY=($(compgen -W "{" ".join(tab_words)}" -- "$cur")); return ;;
        --language) COMPREPLY=($(compgen -W "{" ".join(language_words)}" -- "$cur")); return ;;
        --screenshot|--scenario|--report-pdf) COMPREPLY=($(compgen -f -- "$cur")); return ;;
    esac
    case "$cur" in
        -*) COMPREPLY=($(compgen -W "{" ".join(window_opts)}" -- "$cur")) ;;
        *) COMPREPLY=($(compgen -f -X '!*.@(json|probecycle)' -- "$cur")) ;;
    esac
}}
complete -o filenames -o plusdirs -F _probecycle probecycle
"""
    if not tab_words or not language_words:
        sys.exit("cli_docs.py: the window's --help no longer names its tabs or languages")
    write(out, script)


def write(path, text):
    """`text` to `path` atomically; gzipped (no name, no time: reproducible)
    when the path ends in .gz."""
    tmp = path + ".tmp"
    data = text.encode("utf-8")
    if path.endswith(".gz"):
        buffer = io.BytesIO()
        with gzip.GzipFile(filename="", mode="wb", fileobj=buffer, compresslevel=9, mtime=0) as f:
            f.write(data)
        data = buffer.getvalue()
    with open(tmp, "wb") as f:
        f.write(data)
    os.replace(tmp, path)


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "man-cli":
        man_cli(sys.argv[2], sys.argv[3], sys.argv[4])
    elif len(sys.argv) == 5 and sys.argv[1] == "man-window":
        man_window(sys.argv[2], sys.argv[3], sys.argv[4])
    elif len(sys.argv) == 5 and sys.argv[1] == "completion":
        completion(sys.argv[2], sys.argv[3], sys.argv[4])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
