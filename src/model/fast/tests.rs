//! The reader against the reference parser (the toml crate's spanned
//! tree, `toml::de::DeTable`): every value of the file read, at its place
//! and to its value; and the same read in chunks of any size.

use super::*;

/// The reader reads `text` as the reference parser does
/// (`reference::agrees`), and so does it read in chunks of any size.
pub(in crate::model) fn same(text: &str) {
    if let Err(e) = super::reference::agrees(text) {
        panic!("{e}");
    }
    assert_eq!(in_chunks_the_same_or_declined(text), 0, "{text}");
    in_pieces_the_same_or_declined(text);
}

/// Read in 2 to 5 pieces (`pieces`): the same `RawFile` as read on one
/// core, or declined; never another.
fn in_pieces_the_same_or_declined(text: &str) {
    let whole = format!("{:?}", parse(text));
    for n in 2..=5 {
        if let Some(raw) = pieces::parse_in_pieces(text, n) {
            assert_eq!(format!("{:?}", Some(raw)), whole, "{n} pieces:\n{text}");
        }
    }
}

/// Read in chunks of 1 to 40 tokens: the same `RawFile` as read whole,
/// or declined (should a chunk end inside a value); never another.
/// Returns how many chunk sizes declined (the callers require none).
fn in_chunks_the_same_or_declined(text: &str) -> usize {
    let whole = format!(
        "{:?}",
        parse_in_chunks(text, usize::MAX).expect("read whole")
    );
    let mut declined = 0;
    for n in 1..=40 {
        match parse_in_chunks(text, n) {
            Some(raw) => assert_eq!(format!("{raw:?}"), whole, "chunks of {n}:\n{text}"),
            None => declined += 1,
        }
    }
    declined
}

#[test]
fn a_file_read_in_chunks_of_whole_tables_reads_as_whole() {
    let part = |i: usize| {
        format!(
            "[[part]]\nname = \"p{i}\"\nshape = \"box\"\nmass = {i}\nsize = [1, 2, 3]\ncenter = [{i}, 0, 0]\n"
        )
    };
    let many: String = (1..=30).map(part).collect();
    same(&format!(
        "name = \"n\"\nunits = {{ length = \"mm\" }}\n{many}[analysis]\nomega = [0, 0, 1]\n{}",
        part(31)
    ));
    // Whole tables in every chunk: never declined.
    assert_eq!(in_chunks_the_same_or_declined(&many), 0);
}

#[test]
fn a_line_of_an_array_that_starts_with_a_bracket_does_not_end_a_chunk() {
    // Lines of arrays that start with `[`, as a table header does.
    let text = "[[part]]\nshape = \"plate\"\nmass = 1\ncorner = [0, 0, 0]\nedges = [\n[0, 125, 0],\n[0, 0, 100]]\n\
                [[part]]\nshape = \"box\"\nmass = 1\ncenter = [\n0, 0, 0]\nsize = [\n1,\n2, 3]\n\
                rotation = { matrix = [\n[1, 0, 0],\n[0, 1, 0],\n[0, 0, 1]] }\n";
    same(text);
    // `[1][0]` is no TOML value: declined however it is read.
    let bad = "[[part]]\nshape = \"rod\"\nmass = 1\nfrom = [\n0, 0, 0]\nto = [\n[1][0], 0, 0]\n";
    assert!(toml::from_str::<toml::Table>(bad).is_err());
    for n in [1, 2, 3, 5, usize::MAX] {
        assert!(parse_in_chunks(bad, n).is_none(), "chunks of {n}");
    }
}

/// The reader refuses the file (`explain` words why).
pub(in crate::model) fn declines(text: &str) {
    assert!(read_file(text).is_none(), "fast path accepted:\n{text}");
}

#[test]
fn part_files_read_as_serde_reads_them() {
    same(
        "# comment\nname = \"bent plate\"  # trailing\nunits = { length = \"mm\", mass = \"kg\" }\n\n\
         [[part]]\nname = \"A\"\nshape = \"plate\"\nareal_density = \"70 kg/m^2\"\n\
         corner = [0, 0, 0]\nedges = [[0, 125, 0], [0, 0, 100]]\n\n\
         [[ part ]]\n'name' = \"B \\u00e9\\n\"\nshape = 'box'\nmass = 1_000.5\nsize = [0x10, 0o7, 0b1]\n\
         center = [ -0.0, +1e-3, \"5 mm\" , ]\nrotation = { quaternion = [1, 0, 0, 0] }\n\n\
         [analysis]\nabout = [0, 0, 0]\nomega = [0, 0, \"30 rpm\"]\nalpha = [0, 0, 2]\n",
    );
    same(
        "[units]\nlength = \"in\"\n[[part]]\nshape = \"rod\"\nlinear_density = 2\nlength = 3\n\
         center = [1, 2, 3]\nrotation = { axis = [0, 1, 0], degrees = 90.0 }\n\
         [[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n\
         rotation = { intrinsic = \"zyx\", degrees = [10, 20, 30] }\n\
         [[part]]\nshape = \"box\"\nmass = 1\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\n\
         rotation = { matrix = [[1, 0, 0], [0, 1, 0], [0, 0, 1]] }\n\
         [[part]]\nshape = \"rod\"\nmass = 1\nfrom = [0, 0, 0]\nto = [1, 1, 1]\ndiameter = 0.1\n\
         [[part]]\nshape = \"plate\"\nmass = 1\nsize = [1, 2]\ncenter = [0, 0, 0]\nthickness = \"2 mm\"\n",
    );
    same(
        "[[part]]\nshape = \"cylinder\"\ndensity = \"7850 kg/m^3\"\nradius = 0.25\n\
         inner_radius = \"210 mm\"\nlength = 0.06\ncenter = [0, 0, 0]\n\
         [[part]]\nshape = \"sphere\"\nmass = 1\nradius = 2\ncenter = [1, 0, 0]\n",
    );
    // Values the model rejects are still read: the same errors follow.
    same("[[part]]\nshape = \"sphere\"\nmass = nan\ncenter = [inf, -inf, 1e300]\nsize = []\n");
    same("[[part]]\r\nshape = \"point\"\r\nmass = -1\r\ncenter = [1, 2]\r\n");
    same("name = \"no parts\"\n");
    same("");
}

/// Cut-outs, materials, triangles, given tensors and includes: on the
/// fast path.
#[test]
fn every_key_of_a_shape_reads_as_serde_reads_it() {
    same(
        "[[part]]\nshape = \"box\"\nmaterial = \"steel\"\nsize = [1, 2, 3]\ncenter = [0, 0, 0]\nremove = true\n\
         [[part]]\nshape = \"triangle\"\nareal_density = 2\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\nremove = false\n\
         [[part]]\nshape = \"inertia\"\nmass = 2\ncenter = [1, 2, 3]\ninertia = [[1, 0, 0], [0, 2, 0], [0, 0, 3]]\nproducts = \"positive\"\n\
         [[part]]\nshape = \"plate\"\nmass = 1\narea = 2\ncenter = [0, 0, 0]\n\
         [[part]]\nshape = \"cone\"\ndensity = 2\ndiameter = 2\ninner_diameter = \"1 mm\"\ntop_radius = 0.5\ntop_inner_radius = 0.25\nlength = 3\ncenter = [0, 0, 0]\n\
         [[part]]\nshape = \"torus\"\nmass = 2\nradius = 2\ntube_radius = 1\ninner_tube_radius = 0.5\ncenter = [0, 0, 0]\n\
         [[part]]\nshape = \"prism\"\nmass = 2\npolygon = [[0, 0], [1, 0], [\"1 mm\", 1]]\nlength = 3\norigin = [1, 2, 3]\n\
         [[part]]\nname = \"arm\"\ninclude = \"arm.toml\"\norigin = [1, 2, \"3 mm\"]\nrotation = { axis = [0, 0, 1], degrees = 90 }\n\
         [[part]]\nshape = \"mesh\"\nfile = \"b.stl\"\nmesh_unit = \"mm\"\nmode = \"shell\"\nthickness = 2\ndensity = 3\norigin = [1, 2, 3]\n",
    );
    declines("[[part]]\nshape = \"box\"\nremove = 1\n");
    declines("[[part]]\nshape = \"box\"\nname = true\n");
}

#[test]
fn weight_statements_params_and_includes_read_as_serde_reads_them() {
    let part =
        "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\nmaturity = \"estimated\"\n";
    same(&format!("{part}group = \"a/b\"\n"));
    for table in [
        "[growth]\nestimated = \"15 %\"\n",
        "[budget]\nlimit = 10\n",
        "[params]\nm = \"2 kg\"\nr = 3\n",
    ] {
        same(&format!("{table}{part}"));
        same(&format!("{part}{table}"));
    }
    same(
        "[[part]]\nname = \"arm\"\ninclude = \"arm.toml\"\nparams = { len = \"3 mm\", n = 2 }\n\
         [part.rotation]\naxis = [0, 0, 1]\ndegrees = 90\n",
    );
    same(
        "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n\
         array = { count = 3, step = [1, 0, 0] }\nmirror = { normal = [1, 0, 0], origin = [0, 0, 0] }\n\
         [[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n[part.array]\ncount = 2\naxis = [0, 0, 1]\nstep_degrees = 90\n",
    );
}

#[test]
fn expectations_and_materials_read_as_serde_reads_them() {
    let part = "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    let expect =
        "[expect]\nmass = { max = 2 }\ncenter_of_mass.x = { value = \"0 mm\", tol = \"1 mm\" }\n";
    let materials = "[materials]\nfoam = { density = \"30 kg/m^3\" }\n";
    same(&format!("{part}{expect}"));
    same(&format!(
        "{materials}{part}{part}{expect}[analysis]\nomega = [0, 0, 1]\naxes = {{ x = [0, 1, 0], y = [-1, 0, 0] }}\n"
    ));
    same(&format!("{part}[ expect ]\nmass = {{ max = 2 }}\n{part}"));
    same(&format!("{part}[expect.inertia_com]\nxx = {{ max = 2 }}\n"));
    same(&format!("{part}[materials.steel]\ndensity = 7850\n"));
    same(&format!("expect.mass = {{ max = 2 }}\n{part}"));
    same(&format!(
        "{materials}{part}[materials.steel]\ndensity = 7850\n"
    ));
    same(&format!(
        "{part}{expect}[expect.inertia_com]\nxx = {{ max = 2 }}\n"
    ));
    same(&format!(
        "{part}[expect]\nprincipal_moments = {{ value = [1, 2, \"3 kg m^2\"], tol = \"1 %\" }}\n\
         principal_axes = {{ value = [[1, 0, 0], [0, 1, 0], [0, 0, 1]], tol_degrees = 0.5 }}\nIxx = {{ min = 0 }}\n"
    ));
    declines(&format!("{part}[expect]\nmass = {{ max = }}\n"));
    declines(&format!("{part}[expect]\nmass = {{ maks = 2 }}\n"));
    declines(&format!("{part}[expect]\n[expect]\n"));
    declines(&format!("{part}[[expect]]\n"));
    declines(&format!("{materials}[materials]\n{part}"));
    declines(&format!("{part}[materials]\nfoam = {{ }}\n"));
}

#[test]
fn dotted_keys_sub_tables_and_inline_parts_read_as_serde_reads_them() {
    same("units.length = \"mm\"\n[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n");
    same("part = [{ shape = \"point\", mass = 1, center = [0, 0, 0] }]\n");
    same("[[part]]\nshape = \"box\"\n[part.rotation]\naxis = [0, 0, 1]\ndegrees = 90\n");
    same("[[part]]\nshape = \"box\"\nrotation.axis = [0, 0, 1]\nrotation.degrees = 90\n");
    same("[analysis.axes]\nx = [0, 1, 0]\ny = [1, 0, 0]\n[analysis]\nomega = [0, 0, 1]\n");
    same(
        "[[part]]\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n[expect]\ncenter_of_mass = { x.max = 2, y = { min = 0 } }\n",
    );
    same("part = [{ shape = \"box\", rotation.axis = [0, 0, 1], rotation.degrees = 9 }]\n");
}

#[test]
fn what_toml_or_the_files_form_refuses_is_declined() {
    // Syntax, duplicates, unknown keys, wrong types. (A part missing its
    // shape is read: the model says so, `Ctx::part`.)
    declines("[[part]\nshape = \"point\"\n");
    declines("[[part]]\nshape = \"point\"\nshape = \"box\"\n");
    declines("[[part]]\nshape = \"point\"\nmasss = 1\n");
    declines("[[part]]\nshape = \"point\"\nmass = [1]\n");
    declines("[[part]]\nshape = \"point\"\nmass = true\n");
    same("[[part]]\nmass = 1\n");
    declines("[[part]]\nshape = \"box\"\nrotation = { axis = [0, 0, 1], axis = [1, 0, 0] }\n");
    declines("[analysis]\n[analysis]\n");
    declines("units = { length = \"mm\" }\n[units]\nmass = \"kg\"\n");
    declines("units = { length = \"mm\" }\nunits.mass = \"kg\"\n");
    declines("[[part]]\nshape = \"point\"\nmass = 99999999999999999999999\n");
    declines("[[part]]\nshape = \"point\"\nmass = 1e999\n");
    declines(
        "[[part]]\nshape = \"box\"\nrotation.axis = [0, 0, 1]\n[part.rotation]\ndegrees = 90\n",
    );
    declines("[[part]]\nshape = \"box\"\n[part.rotation]\naxis = [0, 0, 1]\n[part.rotation]\n");
    declines("[[part]]\nshape = \"box\"\n[part]\n");
    declines("part = [{ shape = \"point\" }]\n[[part]]\nshape = \"point\"\n");
    declines("[[analysis]]\n");
    declines("[[part]]\nshape = \"point\"\nmass = 1979-05-27\n");
    declines("name = 1\n");
    declines("[[part]]\nshape = \"point\"\n[[part.x]]\n");
}

/// `n` parts, some unnamed, in the file's units.
fn many_parts(n: usize) -> String {
    let mut text = String::from("name = \"n\"\nunits = { length = \"mm\" }\n");
    for i in 0..n {
        let name = if i % 3 == 0 {
            String::new()
        } else {
            format!("name = \"p{i}\"\n")
        };
        text += &format!(
            "\n[[part]]\n{name}shape = \"box\"\nmass = {i}.5\nsize = [1, 2, 3]\ncenter = [{i}, 0, 0]\n"
        );
    }
    text
}

#[test]
fn a_file_read_in_pieces_reads_as_on_one_core() {
    let text = many_parts(40);
    let whole = format!("{:?}", parse(&text));
    for n in 2..=7 {
        let raw = pieces::parse_in_pieces(&text, n).expect("read in pieces");
        assert_eq!(format!("{:?}", Some(raw)), whole, "{n} pieces");
    }
}

#[test]
fn a_header_line_inside_a_multi_line_string_is_no_place_to_cut() {
    // The second piece would begin inside the string: declined, and the
    // file read on one core as it is.
    let mut text = many_parts(4);
    text += "\n[[part]]\nname = \"\"\"\n[[part]]\nshape = \"box\"\n\"\"\"\nshape = \"point\"\nmass = 1\ncenter = [0, 0, 0]\n";
    text += &many_parts(4).replace("name = \"n\"\nunits = { length = \"mm\" }\n", "");
    assert!(parse(&text).is_some());
    same(&text);
    for n in 2..=9 {
        if let Some(raw) = pieces::parse_in_pieces(&text, n) {
            assert_eq!(format!("{:?}", Some(raw)), format!("{:?}", parse(&text)));
        }
    }
}

#[test]
fn a_table_of_the_file_after_its_parts_declines_the_pieces() {
    // `[units]` after the parts: the later pieces' parts would have been
    // made without it.
    let text =
        many_parts(10).replace("units = { length = \"mm\" }\n", "") + "[units]\nlength = \"mm\"\n";
    assert!(parse(&text).is_some());
    for n in 2..=5 {
        assert!(pieces::parse_in_pieces(&text, n).is_none(), "{n} pieces");
    }
}
