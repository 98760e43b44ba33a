#!/usr/bin/env python3
"""Fails when the graph of the project's library targets (cmake --graphviz) has a cycle, or when a layer reaches
one it must not: the command line (trueturn_cli) no UI library, the runtime (trueturn_runtime) no UI, plot or
report-painting library and no QtGui or QtWidgets.

Usage: check_target_graph.py GRAPH.dot
The dot file lists nodes ("node3" [ label = "trueturn_core_loop" ... ]) and edges ("node3" -> "node1").
"""
import re
import sys


def read_graph(path):
    labels, edges = {}, {}
    for line in open(path, encoding="utf-8"):
        node = re.match(r'\s*"(node\d+)"\s*\[\s*label\s*=\s*"([^"]+)"', line)
        if node:
            labels[node.group(1)] = node.group(2)
        edge = re.match(r'\s*"(node\d+)"\s*->\s*"(node\d+)"', line)
        if edge:
            edges.setdefault(edge.group(1), set()).add(edge.group(2))
    names = {n: l for n, l in labels.items() if l.startswith("trueturn")}
    return labels, names, edges


def reaches(labels, edges, start):
    """Every label reachable from the node labelled `start` (itself excluded)."""
    begin = [n for n, l in labels.items() if l == start]
    seen, todo = set(), list(begin)
    while todo:
        for m in edges.get(todo.pop(), ()):
            if m not in seen:
                seen.add(m)
                todo.append(m)
    return {labels[n] for n in seen if n in labels}


# A layer and what it must never reach, directly or through another target.
FORBIDDEN = {
    "trueturn_cli": {"trueturn_ui"},
    "trueturn_runtime": {"trueturn_ui", "trueturn_plot", "trueturn_reports", "Qt6::Gui", "Qt6::Widgets",
                         "Qt6::PrintSupport"},
}


def layer_problems(labels, edges):
    problems = []
    for layer, banned in FORBIDDEN.items():
        if layer not in labels.values():
            problems.append(f"{layer} is missing from the graph")
            continue
        bad = sorted(reaches(labels, edges, layer) & banned)
        if bad:
            problems.append(f"{layer} reaches {', '.join(bad)}")
    return problems


def find_cycle(names, edges):
    state, stack = {}, []

    def visit(n):
        state[n] = "open"
        stack.append(n)
        for m in sorted(edges.get(n, ())):
            if state.get(m) == "open":
                return stack[stack.index(m):] + [m]
            if m not in state:
                found = visit(m)
                if found:
                    return found
        stack.pop()
        state[n] = "done"
        return None

    for n in sorted(names):
        if n not in state:
            found = visit(n)
            if found:
                return [names[x] for x in found]
    return None


labels, names, all_edges = read_graph(sys.argv[1])
edges = {n: {m for m in e if m in names} for n, e in all_edges.items() if n in names}
cores = [l for l in names.values() if l.startswith("trueturn_core_")]
if len(cores) < 5:
    sys.exit(f"the graph names only {len(cores)} core areas; is {sys.argv[1]} the project's graph?")
cycle = find_cycle(names, edges)
if cycle:
    sys.exit("the target graph has a cycle: " + " -> ".join(cycle))
problems = layer_problems(labels, all_edges)
if problems:
    sys.exit("a layer reaches one it must not: " + "; ".join(problems))
print(f"{len(names)} targets ({len(cores)} core areas), {sum(len(e) for e in edges.values())} links, no cycle")
