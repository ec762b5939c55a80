//! Graph module: seed examples, properties against brute-force oracles, bad input.

use compgeo::count::Counts;
use compgeo::graph::*;
use compgeo::Error;
use proptest::prelude::*;

/// A random simple-or-not graph: n in 1..=max_n, up to max_m edges (loops and repeats
/// allowed, the graph type must cope).
fn arb_edges(max_n: usize, max_m: usize) -> impl Strategy<Value = (usize, Vec<[usize; 2]>)> {
    (1..=max_n).prop_flat_map(move |n| {
        (
            Just(n),
            prop::collection::vec((0..n, 0..n).prop_map(|(u, v)| [u, v]), 0..=max_m),
        )
    })
}

/// Naive adjacency matrix, the oracle's view of the graph.
fn matrix(n: usize, edges: &[[usize; 2]]) -> Vec<Vec<bool>> {
    let mut a = vec![vec![false; n]; n];
    for &[u, v] in edges {
        if u != v {
            a[u][v] = true;
            a[v][u] = true;
        }
    }
    a
}

/// Distances from `s` by repeated relaxation (Bellman–Ford with unit weights).
fn distances(a: &[Vec<bool>], s: usize) -> Vec<Option<usize>> {
    let n = a.len();
    let mut d = vec![None; n];
    d[s] = Some(0);
    for _ in 0..n {
        for u in 0..n {
            for v in 0..n {
                if a[u][v] {
                    if let Some(du) = d[u] {
                        if d[v].is_none_or(|dv| du + 1 < dv) {
                            d[v] = Some(du + 1);
                        }
                    }
                }
            }
        }
    }
    d
}

/// The textbook recursive DFS on the matrix, smallest neighbour first.
fn recursive_dfs(a: &[Vec<bool>], x: usize, seen: &mut [bool], order: &mut Vec<usize>) {
    seen[x] = true;
    order.push(x);
    for y in 0..a.len() {
        if a[x][y] && !seen[y] {
            recursive_dfs(a, y, seen, order);
        }
    }
}

/// The toy graph of the seed's search example (003 §2.1 "Algoritmos de búsqueda"), vertices
/// a..g as 0..6. The figure is lost from the text; these are the edges both printed tables
/// imply: ab, ad, bc, bd, be, bf, bg, ce, ef.
fn seed_toys() -> Graph {
    let e = |s: &str| {
        let b = s.as_bytes();
        [(b[0] - b'a') as usize, (b[1] - b'a') as usize]
    };
    let edges: Vec<_> = ["ab", "ad", "bc", "bd", "be", "bf", "bg", "ce", "ef"]
        .iter()
        .map(|s| e(s))
        .collect();
    Graph::from_edges(7, &edges).unwrap()
}

fn letter(v: usize) -> String {
    char::from(b'a' + v as u8).to_string()
}

/// The seed's table as (add, remove, Q) strings, `-` for empty, `∅` for an empty Q.
fn seed_rows(rows: &[(&str, &str, &str)]) -> String {
    let mut s = String::from("Add\tRemove\tQ\n");
    for (a, r, q) in rows {
        s += &format!("{a}\t{r}\t{q}\n");
    }
    s
}

#[test]
fn seed_dfs_table() {
    let rows = search_trace(&seed_toys(), 0, SearchKind::Depth).unwrap();
    let expected = seed_rows(&[
        ("a", "-", "a"),
        ("b", "-", "ab"),
        ("c", "-", "abc"),
        ("e", "-", "abce"),
        ("f", "-", "abcef"),
        ("-", "f", "abce"),
        ("-", "e", "abc"),
        ("-", "c", "ab"),
        ("d", "-", "abd"),
        ("-", "d", "ab"),
        ("g", "-", "abg"),
        ("-", "g", "ab"),
        ("-", "b", "a"),
        ("-", "a", "∅"),
    ]);
    assert_eq!(trace_table(&rows, letter), expected);
    let added: Vec<_> = rows.iter().filter_map(|r| r.added).collect();
    assert_eq!(added, dfs(&seed_toys(), 0).unwrap().order);
}

#[test]
fn seed_bfs_table() {
    let rows = search_trace(&seed_toys(), 0, SearchKind::Breadth).unwrap();
    let expected = seed_rows(&[
        ("a", "-", "a"),
        ("b", "-", "ab"),
        ("d", "-", "abd"),
        ("-", "a", "bd"),
        ("c", "-", "bdc"),
        ("e", "-", "bdce"),
        ("f", "-", "bdcef"),
        ("g", "-", "bdcefg"),
        ("-", "b", "dcefg"),
        ("-", "d", "cefg"),
        ("-", "c", "efg"),
        ("-", "e", "fg"),
        ("-", "f", "g"),
        ("-", "g", "∅"),
    ]);
    assert_eq!(trace_table(&rows, letter), expected);
    let added: Vec<_> = rows.iter().filter_map(|r| r.added).collect();
    assert_eq!(added, bfs(&seed_toys(), 0).unwrap().order);
}

#[test]
fn search_errors_name_the_vertex() {
    let g = Graph::from_edges(3, &[[0, 1]]).unwrap();
    let e = bfs(&g, 3).unwrap_err();
    assert!(
        matches!(
            e,
            Error::NoSuchVertex {
                vertex: 3,
                vertices: 3
            }
        ),
        "{e}"
    );
    assert!(matches!(
        Graph::from_edges(2, &[[0, 1], [2, 0]]),
        Err(Error::VertexOutOfRange {
            edge: 1,
            vertex: 2,
            vertices: 2
        })
    ));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn graph_matches_the_adjacency_matrix((n, edges) in arb_edges(12, 40)) {
        let g = Graph::from_edges(n, &edges).unwrap();
        let a = matrix(n, &edges);
        for u in 0..n {
            let expected: Vec<usize> = (0..n).filter(|&v| a[u][v]).collect();
            prop_assert_eq!(g.neighbours(u).collect::<Vec<_>>(), expected);
        }
        let distinct: usize = (0..n).map(|u| (u + 1..n).filter(|&v| a[u][v]).count()).sum();
        prop_assert_eq!(g.edge_count(), distinct);
        let loops = edges.iter().filter(|e| e[0] == e[1]).count();
        prop_assert_eq!(g.loops_dropped(), loops);
        prop_assert_eq!(g.parallel_merged(), edges.len() - loops - distinct);
    }

    #[test]
    fn bfs_gives_shortest_path_trees((n, edges) in arb_edges(12, 30), s in 0usize..12) {
        let s = s % n;
        let g = Graph::from_edges(n, &edges).unwrap();
        let mut c = Counts::default();
        let r = bfs_with(&g, s, &mut c).unwrap();
        prop_assert!(is_search_tree(&g, s, &r));
        let d = distances(&matrix(n, &edges), s);
        // The component, each vertex once, in nondecreasing distance.
        let reached: Vec<usize> = (0..n).filter(|&v| d[v].is_some()).collect();
        let mut sorted = r.order.clone();
        sorted.sort_unstable();
        prop_assert_eq!(&sorted, &reached);
        prop_assert!(r.order.windows(2).all(|w| d[w[0]] <= d[w[1]]));
        for &v in &r.order[1..] {
            let p = r.parent[v].unwrap();
            prop_assert_eq!(d[v], d[p].map(|x| x + 1));
        }
        let degree_sum: usize = r.order.iter().map(|&v| g.degree(v)).sum();
        prop_assert_eq!(c.vertex_visits, r.order.len() as u64);
        prop_assert_eq!(c.edge_visits, degree_sum as u64);
    }

    #[test]
    fn dfs_matches_the_recursive_definition((n, edges) in arb_edges(12, 30), s in 0usize..12) {
        let s = s % n;
        let g = Graph::from_edges(n, &edges).unwrap();
        let mut c = Counts::default();
        let r = dfs_with(&g, s, &mut c).unwrap();
        prop_assert!(is_search_tree(&g, s, &r));
        let mut seen = vec![false; n];
        let mut order = Vec::new();
        recursive_dfs(&matrix(n, &edges), s, &mut seen, &mut order);
        prop_assert_eq!(&r.order, &order);
        let degree_sum: usize = r.order.iter().map(|&v| g.degree(v)).sum();
        prop_assert_eq!(c.edge_visits, degree_sum as u64);
        let trace = search_trace(&g, s, SearchKind::Depth).unwrap();
        prop_assert_eq!(trace.len(), 2 * order.len());
        prop_assert!(trace.last().unwrap().list.is_empty());
    }

    #[test]
    fn components_partition_by_reachability((n, edges) in arb_edges(12, 20)) {
        let g = Graph::from_edges(n, &edges).unwrap();
        let c = components(&g);
        let a = matrix(n, &edges);
        for u in 0..n {
            let d = distances(&a, u);
            for v in 0..n {
                prop_assert_eq!(c.label[u] == c.label[v], d[v].is_some());
            }
        }
        prop_assert_eq!(c.count, c.label.iter().max().map_or(0, |m| m + 1));
        prop_assert_eq!(is_connected(&g), c.count == 1);
    }
}
