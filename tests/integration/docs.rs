//! The documents that restate the program's own tables say what the
//! program does.

use massprop::shapes::SHAPES;

/// docs/part-file.md lists each shape's keys exactly as `shapes::SHAPES`
/// describes them: the docs read the one description, as validation does.
#[test]
fn the_part_file_reference_lists_each_shapes_keys_from_the_shape_table() {
    let doc = std::fs::read_to_string("docs/part-file.md").unwrap();
    let begin = doc.find("<!-- keys-by-shape: begin -->\n").unwrap();
    let end = doc.find("<!-- keys-by-shape: end -->").unwrap();
    let table = &doc[begin..end];
    let mut want = String::from(
        "<!-- keys-by-shape: begin -->\n| shape | keys | degenerate when |\n|---|---|---|\n",
    );
    for s in &SHAPES {
        let keys: Vec<String> = s.keys.iter().map(|k| format!("`{k}`")).collect();
        want.push_str(&format!(
            "| `{}` | {} | {} |\n",
            s.name,
            keys.join(", "),
            s.degenerate
        ));
    }
    assert_eq!(table, want, "docs/part-file.md's keys-by-shape table");
    // The shape table above it has one row per shape, with its density key.
    for s in &SHAPES {
        let row = doc
            .lines()
            .find(|l| l.starts_with(&format!("| `{}` | ", s.name)) && l.matches('|').count() == 6)
            .unwrap_or_else(|| panic!("no row for `{}` in the shape table", s.name));
        match s.density {
            Some(d) => assert!(row.contains(&format!("`{}`", d.key)), "{row}"),
            None => assert!(row.contains("only `mass`"), "{row}"),
        }
    }
}

/// Every document that lists the shapes names each of them: README's list,
/// docs/json.md's `shape` values, docs/part-file.md's tables.
#[test]
fn the_documents_that_list_the_shapes_name_every_shape() {
    let readme = std::fs::read_to_string("README.md").unwrap();
    let list = readme
        .split("\n\n")
        .find(|p| p.starts_with("Shapes `"))
        .expect("README.md has a paragraph that lists the shapes");
    let json = std::fs::read_to_string("docs/json.md").unwrap();
    let part_file = std::fs::read_to_string("docs/part-file.md").unwrap();
    for s in &SHAPES {
        assert!(
            list.contains(&format!("`{}`", s.name)),
            "README.md: `{}`",
            s.name
        );
        assert!(
            json.contains(&format!("`\"{}\"`", s.name)),
            "docs/json.md: `{}`",
            s.name
        );
        assert!(
            part_file.contains(&format!("| `{}` | ", s.name)),
            "docs/part-file.md: `{}`",
            s.name
        );
    }
}
