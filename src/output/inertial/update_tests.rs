//! `update`'s tests: every byte but the inertial's kept.
use super::*;
use crate::robot::Tensor;

/// Numbers no short decimal holds, and one that needs an exponent.
fn export() -> Export {
    Export {
        mass: 1.0 / 3.0,
        pos: [0.1 + 0.2, -2.5e-7, 0.0],
        tensor: Tensor {
            xx: 2.0 / 3.0,
            yy: 0.7,
            zz: 1e-9 / 7.0,
            xy: -1.0 / 7.0,
            xz: 0.0,
            yz: 3e20,
        },
        principal: None,
    }
}

/// Mass, position and the tensor (xx yy zz xy xz yz) of an inertial
/// element as written, read back with roxmltree alone.
fn read_back(format: Dialect, element: &str) -> (f64, Vec<f64>, Vec<f64>) {
    let doc = Document::parse(element).unwrap();
    let root = doc.root_element();
    let child = |name: &str| {
        root.descendants()
            .find(|n| n.has_tag_name(name))
            .unwrap_or_else(|| panic!("no <{name}> in {element}"))
    };
    let list = |s: &str| -> Vec<f64> { s.split_whitespace().map(|v| v.parse().unwrap()).collect() };
    let one = |s: &str| -> f64 { s.trim().parse().unwrap() };
    let order = ["ixx", "iyy", "izz", "ixy", "ixz", "iyz"];
    match format {
        Dialect::Urdf => {
            let inertia = child("inertia");
            (
                one(child("mass").attribute("value").unwrap()),
                list(child("origin").attribute("xyz").unwrap()),
                order
                    .iter()
                    .map(|k| one(inertia.attribute(*k).unwrap()))
                    .collect(),
            )
        }
        Dialect::Sdf => (
            one(child("mass").text().unwrap()),
            list(child("pose").text().unwrap())[..3].to_vec(),
            order
                .iter()
                .map(|k| one(child(k).text().unwrap()))
                .collect(),
        ),
        Dialect::Mjcf => (
            one(root.attribute("mass").unwrap()),
            list(root.attribute("pos").unwrap()),
            list(root.attribute("fullinertia").unwrap()),
        ),
    }
}

/// `update` changes `text` only where `old` (once in it) was: the bytes
/// before and after are the same, and in its place is `e`'s element at
/// `indent`, with the file's line endings, whose numbers read back to
/// the bit. Returns the result.
fn assert_replaced(text: &str, format: Dialect, link: &str, old: &str, indent: &str) -> String {
    assert_eq!(
        text.matches(old).count(),
        1,
        "the test's old element is in the text once"
    );
    let e = export();
    let start = text.find(old).unwrap();
    let suffix = &text[start + old.len()..];
    let out = update(text, format, link, &e).unwrap();
    assert_eq!(out[..start], text[..start], "the bytes before are kept");
    assert!(out.ends_with(suffix), "the bytes after are kept:\n{out}");
    let new = &out[start..out.len() - suffix.len()];
    let nl = if text.contains("\r\n") { "\r\n" } else { "\n" };
    assert_eq!(new, inertial_element(format, &e, indent).replace('\n', nl));
    let (mass, pos, tensor) = read_back(format, new);
    let t = e.tensor;
    let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
    assert_eq!(mass.to_bits(), e.mass.to_bits());
    assert_eq!(bits(&pos), bits(&e.pos));
    assert_eq!(bits(&tensor), bits(&[t.xx, t.yy, t.zz, t.xy, t.xz, t.yz]));
    let options = ParsingOptions {
        allow_dtd: true,
        ..ParsingOptions::default()
    };
    Document::parse_with_options(&out, options).unwrap();
    out
}

const URDF: &str = r#"<?xml version="1.0" encoding="utf-8"?>
<!-- A two-link arm. <link name="arm"> in a comment is not a link. -->
<robot name='arm' xmlns:xacro="http://www.ros.org/wiki/xacro">
   <link name='base'>
      <inertial>
        <origin xyz="0 0 0.1" rpy="0 0 0" />
        <mass value='5.0'/>
        <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>
      </inertial>
      <visual><geometry><box size="1 1 1"/></geometry></visual>
   </link>
   <joint name="shoulder" type='revolute'>
      <parent link="base"/>  <child link="arm"/>
   </joint>
   <link name="arm" >   <!-- from CAD, 2019 -->
      <!-- the inertial below is stale -->
      <inertial>
         <origin xyz='0 0 0.5'/>
         <mass value="1"/>
         <inertia ixx="0.1" iyy="0.1" izz="0.01" ixy="0" ixz="0" iyz="0"/>
      </inertial>
      <collision name="c&gt;"><geometry><cylinder radius=".05" length="1"/></geometry></collision>
   </link>
</robot>   
"#;

const URDF_ARM: &str = r#"<inertial>
         <origin xyz='0 0 0.5'/>
         <mass value="1"/>
         <inertia ixx="0.1" iyy="0.1" izz="0.01" ixy="0" ixz="0" iyz="0"/>
      </inertial>"#;

#[test]
fn a_urdf_links_inertial_is_replaced_and_nothing_else() {
    assert_replaced(URDF, Dialect::Urdf, "arm", URDF_ARM, "      ");
}

#[test]
fn a_crlf_file_keeps_its_line_endings() {
    let crlf = URDF.replace('\n', "\r\n");
    let out = assert_replaced(
        &crlf,
        Dialect::Urdf,
        "arm",
        &URDF_ARM.replace('\n', "\r\n"),
        "      ",
    );
    assert_eq!(out.matches('\n').count(), out.matches("\r\n").count());
}

#[test]
fn a_tab_indented_file_keeps_its_tabs() {
    let tabs = URDF.replace("      <", "\t\t<");
    let old = URDF_ARM.replace("      <", "\t\t<");
    assert_replaced(&tabs, Dialect::Urdf, "arm", &old, "\t\t");
}

#[test]
fn an_inertial_on_the_line_of_its_link_is_replaced_in_place() {
    let text =
        "<robot>\n  <link name=\"a\"><inertial><mass value=\"1\"/></inertial></link>\n</robot>\n";
    let out = assert_replaced(
        text,
        Dialect::Urdf,
        "a",
        "<inertial><mass value=\"1\"/></inertial>",
        "  ",
    );
    assert!(out.starts_with("<robot>\n  <link name=\"a\"><inertial>\n    <origin"));
}

#[test]
fn a_doctype_is_no_obstacle() {
    let text = format!(
        "<!DOCTYPE robot>\n{}",
        &URDF[URDF.find("<robot").unwrap()..]
    );
    assert_replaced(&text, Dialect::Urdf, "arm", URDF_ARM, "      ");
}

const SDF: &str = "<?xml version='1.0'?>
<sdf version=\"1.9\">
  <model name=\"robot\">
    <link name=\"base\">
      <inertial><mass>10</mass></inertial>
    </link>
    <model name='gripper'>
      <plugin name=\"p\" filename=\"p.so\"><link name=\"finger\"/></plugin>
      <link name=\"finger\">
        <pose>0 0 0.1 0 0 0</pose>
        <inertial auto=\"false\">
          <pose>0 0 0 0 0 0</pose>
          <mass>0.1</mass>
          <!-- no inertia given -->
        </inertial>
      </link>
    </model>
  </model>
</sdf>
";

const SDF_FINGER: &str = "<inertial auto=\"false\">
          <pose>0 0 0 0 0 0</pose>
          <mass>0.1</mass>
          <!-- no inertia given -->
        </inertial>";

#[test]
fn links_of_several_top_level_models_are_named_with_their_model() {
    // As robot::read names them: `a::l` and `b::l`, and `l` is none.
    let text = "<sdf version='1.9'><world name='w'><model name='a'><link name='l'/></model><model name='b'><link name='l'/></model></world></sdf>";
    let out = update(text, Dialect::Sdf, "b::l", &export()).unwrap();
    assert!(out.starts_with(&text[..text.find("<model name='b'>").unwrap()]));
    assert!(matches!(
        update(text, Dialect::Sdf, "l", &export()),
        Err(UpdateError::NoLink { .. })
    ));
    let names: Vec<String> =
        crate::robot::read::read(&crate::diag::Source::new("w.sdf", text), Dialect::Sdf)
            .unwrap()
            .links
            .into_iter()
            .map(|l| l.name)
            .collect();
    assert_eq!(names, ["a::l", "b::l"]);
}

#[test]
fn a_nested_sdformat_models_link_is_named_from_the_outermost() {
    assert_replaced(SDF, Dialect::Sdf, "gripper::finger", SDF_FINGER, "        ");
    assert_replaced(
        SDF,
        Dialect::Sdf,
        "base",
        "<inertial><mass>10</mass></inertial>",
        "      ",
    );
}

#[test]
fn an_sdformat_crlf_file_keeps_its_line_endings() {
    let crlf = SDF.replace('\n', "\r\n");
    assert_replaced(
        &crlf,
        Dialect::Sdf,
        "gripper::finger",
        &SDF_FINGER.replace('\n', "\r\n"),
        "        ",
    );
}

const MJCF: &str = r#"<mujoco model="arm">
  <compiler angle="radian"/>
  <default><joint damping="1"/></default>
  <worldbody>
    <light pos="0 0 3"/>
    <body name="upper" pos="0 0 1">
      <joint name="shoulder"/>
      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>
      <geom type="capsule" size=".05 .5"/>
      <body name='lower' pos="0 0 1">
	<joint name="elbow"/>
	<inertial pos='0 0 0.2' mass='0.5' fullinertia='1 1 1 0 0 0' />
      </body>
    </body>
  </worldbody>
</mujoco>
"#;

#[test]
fn an_mjcf_body_anywhere_under_worldbody_is_found() {
    let lower = "<inertial pos='0 0 0.2' mass='0.5' fullinertia='1 1 1 0 0 0' />";
    assert_replaced(MJCF, Dialect::Mjcf, "lower", lower, "\t");
    let upper = r#"<inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>"#;
    assert_replaced(MJCF, Dialect::Mjcf, "upper", upper, "      ");
}

#[test]
fn an_mjcf_crlf_file_keeps_its_line_endings() {
    let lower = "<inertial pos='0 0 0.2' mass='0.5' fullinertia='1 1 1 0 0 0' />";
    assert_replaced(
        &MJCF.replace('\n', "\r\n"),
        Dialect::Mjcf,
        "lower",
        lower,
        "\t",
    );
}

#[test]
fn a_missing_inertial_is_inserted_as_the_first_child_one_step_in() {
    let text =
        "<robot name=\"r\">\n    <link name=\"a\">\n        <visual/>\n    </link>\n</robot>\n";
    let e = export();
    let element = inertial_element(Dialect::Urdf, &e, "        ");
    assert_eq!(
        update(text, Dialect::Urdf, "a", &e).unwrap(),
        format!(
            "<robot name=\"r\">\n    <link name=\"a\">\n        {element}\n        <visual/>\n    </link>\n</robot>\n"
        )
    );
}

#[test]
fn an_inserted_inertial_takes_the_files_tabs_and_crlf() {
    let text = "<mujoco>\r\n<worldbody>\r\n\t<body name=\"b\">\r\n\t\t<geom size=\"1\"/>\r\n\t</body>\r\n</worldbody>\r\n</mujoco>";
    let e = export();
    let element = inertial_element(Dialect::Mjcf, &e, "\t\t");
    assert_eq!(
        update(text, Dialect::Mjcf, "b", &e).unwrap(),
        format!(
            "<mujoco>\r\n<worldbody>\r\n\t<body name=\"b\">\r\n\t\t{element}\r\n\t\t<geom size=\"1\"/>\r\n\t</body>\r\n</worldbody>\r\n</mujoco>"
        )
    );
    let sdf = "<sdf>\r\n\t<model name=\"m\">\r\n\t\t<link name=\"l\">\r\n\t\t\t<pose>0 0 0 0 0 0</pose>\r\n\t\t</link>\r\n\t</model>\r\n</sdf>\r\n";
    let element = inertial_element(Dialect::Sdf, &e, "\t\t\t").replace('\n', "\r\n");
    assert_eq!(
        update(sdf, Dialect::Sdf, "l", &e).unwrap(),
        format!(
            "<sdf>\r\n\t<model name=\"m\">\r\n\t\t<link name=\"l\">\r\n\t\t\t{element}\r\n\t\t\t<pose>0 0 0 0 0 0</pose>\r\n\t\t</link>\r\n\t</model>\r\n</sdf>\r\n"
        )
    );
}

#[test]
fn an_empty_element_link_is_opened_around_its_new_inertial() {
    let text = "<robot>\n\t<link name=\"base\"/>\n\t<link name='tip' />\n</robot>";
    let e = export();
    let element = inertial_element(Dialect::Urdf, &e, "\t\t");
    let out = update(text, Dialect::Urdf, "tip", &e).unwrap();
    assert_eq!(
        out,
        format!(
            "<robot>\n\t<link name=\"base\"/>\n\t<link name='tip'>\n\t\t{element}\n\t</link>\n</robot>"
        )
    );
    // And one with nothing inside its two tags.
    let text = "<robot>\n  <link name=\"tip\"></link>\n</robot>";
    let element = inertial_element(Dialect::Urdf, &e, "    ");
    assert_eq!(
        update(text, Dialect::Urdf, "tip", &e).unwrap(),
        format!("<robot>\n  <link name=\"tip\">\n    {element}\n  </link>\n</robot>")
    );
}

#[test]
fn a_missing_link_is_an_error_that_lists_names_and_suggests_one() {
    let err = update(URDF, Dialect::Urdf, "armm", &export()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "no link named \"armm\" (the file has \"base\", \"arm\"); did you mean \"arm\"?"
    );
    assert_eq!(err.at(), None);
    let many: String = (1..=8).map(|i| format!("<body name=\"b{i}\"/>")).collect();
    let text = format!("<mujoco><worldbody>{many}</worldbody></mujoco>");
    let err = update(&text, Dialect::Mjcf, "hand", &export()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "no body named \"hand\" (the file has \"b1\", \"b2\", \"b3\", \"b4\", \"b5\" and 3 more)"
    );
    // A <link> inside an SDFormat plugin is not one of the model's.
    let err = update(SDF, Dialect::Sdf, "finger", &export()).unwrap_err();
    assert!(
        matches!(err, UpdateError::NoLink { ref names, .. } if names == &["base", "gripper::finger"])
    );
    let err = update("<robot/>", Dialect::Urdf, "a", &export()).unwrap_err();
    assert_eq!(err.to_string(), "no link named \"a\": the file has none");
}

#[test]
fn two_links_of_one_name_are_an_error_at_the_second() {
    let text = "<robot>\n<link name=\"a\"/>\n<link name=\"a\"/>\n</robot>";
    let err = update(text, Dialect::Urdf, "a", &export()).unwrap_err();
    assert_eq!(err.to_string(), "more than one link named \"a\"");
    assert_eq!(err.at(), Some(text.rfind("<link").unwrap()));
}

#[test]
fn two_inertials_in_a_link_are_an_error_at_the_second() {
    let text = "<mujoco><worldbody><body name=\"b\">\n<inertial mass=\"1\"/>\n<inertial mass=\"2\"/>\n</body></worldbody></mujoco>";
    let err = update(text, Dialect::Mjcf, "b", &export()).unwrap_err();
    assert_eq!(err.to_string(), "body \"b\" has more than one <inertial>");
    assert_eq!(err.at(), Some(text.rfind("<inertial").unwrap()));
}

#[test]
fn text_that_is_not_xml_is_an_error_with_its_place() {
    let text = "<robot>\n  <link name=\"a\">\n</robot>";
    let err = update(text, Dialect::Urdf, "a", &export()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "not well-formed XML: expected 'link' tag, not 'robot'"
    );
    assert_eq!(err.at(), text.find("</robot>"));
    // Past the first line, the column counts characters, not bytes.
    let text = "<robot>\n<link name=\"é\" x=1/></robot>";
    let err = update(text, Dialect::Urdf, "a", &export()).unwrap_err();
    assert_eq!(err.at(), text.find('1'));
}

#[test]
fn models_nested_too_deep_are_an_error_not_a_stack_overflow() {
    // SDFormat models are walked recursively: 100,000 nested ones
    // overflowed the stack.
    let n = 100_000;
    let text = format!(
        "<sdf version='1.9'>{}{}</sdf>",
        "<model name='m'><link name='l'/>".repeat(n),
        "</model>".repeat(n)
    );
    let err = update(&text, Dialect::Sdf, "l", &export()).unwrap_err();
    assert!(
        err.to_string().contains("is nested 1000 elements deep"),
        "{err}"
    );
    // The first element at depth 1000 (`<sdf>` is at 1): the link of
    // the 998th model.
    let model = |k: usize| "<sdf version='1.9'>".len() + 32 * (k - 1);
    assert_eq!(err.at(), Some(model(998) + "<model name='m'>".len()));
}

#[test]
fn a_root_element_of_another_format_is_an_error() {
    let err = update(SDF, Dialect::Urdf, "base", &export()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the root element is <sdf>, not the <robot> of a urdf file"
    );
    assert_eq!(err.at(), Some(SDF.find("<sdf").unwrap()));
}

#[test]
fn the_diff_of_an_update_shows_the_old_and_new_inertial() {
    let out = update(MJCF, Dialect::Mjcf, "upper", &export()).unwrap();
    let diff = super::super::unified_diff(MJCF, &out, "arm.xml");
    let old = r#"      <inertial pos="0 0 0" mass="1" diaginertia="1 1 1"/>"#;
    let new = format!(
        "      {}",
        inertial_element(Dialect::Mjcf, &export(), "      ")
    );
    assert_eq!(
        diff,
        format!(
            "--- a/arm.xml\n+++ b/arm.xml\n@@ -5,7 +5,7 @@\n     <light pos=\"0 0 3\"/>\n     <body name=\"upper\" pos=\"0 0 1\">\n       <joint name=\"shoulder\"/>\n-{old}\n+{new}\n       <geom type=\"capsule\" size=\".05 .5\"/>\n       <body name='lower' pos=\"0 0 1\">\n \t<joint name=\"elbow\"/>\n"
        )
    );
}
