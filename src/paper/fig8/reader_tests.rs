//! The reader of measured data: every error names the file, the row and the column.
use super::*;

const HEADER: &str = "series,source,contact,rx_m,ry_m,e_prime_pa,ph_pa,temperature_c,um_m_s,slip,mu,tau0_pa,lubricant,viscosity_law,film_formula";

fn row(cells: &str) -> String {
    format!("# a comment\n{HEADER}\n{cells}\n")
}

const GOOD: &str = "A,\"Test, not measured\",elliptical,1.03875e-2,,226e9,3e9,40,12,0.005,0.05,4e6,mineral-oil-a,roelands,eq10";

#[test]
fn a_good_row_parses_and_transforms() {
    let d = parse("t.csv", &row(GOOD)).unwrap();
    assert_eq!(d.rows.len(), 1);
    let r = &d.rows[0];
    assert_eq!((r.row, r.line), (1, 3));
    assert_eq!(r.source, "Test, not measured");
    assert_eq!(
        r.point.contact,
        Contact::Elliptical {
            rx_m: 1.03875e-2,
            ry_m: 1.03875e-2
        }
    );
    let t = transform(&d, &LubricantTable::table1()).unwrap();
    // mu p_H / tau0 = 0.05 * 3e9 / 4e6.
    assert!((t[0].reduced.mu_bar - 37.5).abs() < 1e-12);
}

#[test]
fn errors_name_file_row_and_column() {
    let lubs = LubricantTable::table1();
    let e = |cells: &str| parse("my.csv", &row(cells)).unwrap_err().to_string();
    let msg = e(&GOOD.replace(",0.05,", ",abc,"));
    assert!(msg.starts_with("my.csv: row 1 (line 3): mu:"), "{msg}");
    let msg = e(&GOOD.replace("\"Test, not measured\"", ""));
    assert!(msg.contains("source: required"), "{msg}");
    let msg = e(&GOOD.replace("elliptical", "round"));
    assert!(msg.contains("contact:"), "{msg}");
    let msg = e(&GOOD.replace(",eq10", ",hamrock"));
    assert!(msg.contains("film_formula:"), "{msg}");
    let msg = e(&GOOD.replace(",roelands,", ",,"));
    assert!(msg.contains("viscosity_law: required"), "{msg}");
    let msg = e(&GOOD.replace(",12,", ",,"));
    assert!(msg.contains("um_m_s: required"), "{msg}");
    // Header problems.
    let msg = parse("my.csv", "source,bogus\n").unwrap_err().to_string();
    assert!(msg.contains("header") && msg.contains("bogus"), "{msg}");
    let msg = parse("my.csv", "source\nx\n").unwrap_err().to_string();
    assert!(msg.contains("missing column 'contact'"), "{msg}");
    let msg = parse("my.csv", &format!("{HEADER}\n1,2\n"))
        .unwrap_err()
        .to_string();
    assert!(
        msg.contains("row 1 (line 2)") && msg.contains("cells"),
        "{msg}"
    );
    // Transform errors name the row's column.
    let d = parse("my.csv", &row(&GOOD.replace(",3e9,", ",-3e9,"))).unwrap();
    let msg = transform(&d, &lubs).unwrap_err().to_string();
    assert!(msg.starts_with("my.csv: row 1 (line 3): ph_pa:"), "{msg}");
    let d = parse("my.csv", &row(&GOOD.replace(",40,", ",20,"))).unwrap();
    let msg = transform(&d, &lubs).unwrap_err().to_string();
    assert!(msg.contains("temperature_c:"), "{msg}");
    let d = parse("my.csv", &row(&GOOD.replace("mineral-oil-a", "castor"))).unwrap();
    let msg = transform(&d, &lubs).unwrap_err().to_string();
    assert!(
        msg.contains("lubricant:") && msg.contains("castor"),
        "{msg}"
    );
}

#[test]
fn a_missing_folder_holds_no_dataset() {
    assert!(read_folder(Path::new("/nonexistent/fig8"))
        .unwrap()
        .is_empty());
}
