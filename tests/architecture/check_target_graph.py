#!/usr/bin/env python3
"""Fails when the graph of the project's library targets (cmake --graphviz) has a cycle.

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
    return names, {n: {m for m in e if m in names} for n, e in edges.items() if n in names}


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


names, edges = read_graph(sys.argv[1])
cores = [l for l in names.values() if l.startswith("trueturn_core_")]
if len(cores) < 5:
    sys.exit(f"the graph names only {len(cores)} core areas; is {sys.argv[1]} the project's graph?")
cycle = find_cycle(names, edges)
if cycle:
    sys.exit("the target graph has a cycle: " + " -> ".join(cycle))
print(f"{len(names)} targets ({len(cores)} core areas), {sum(len(e) for e in edges.values())} links, no cycle")
