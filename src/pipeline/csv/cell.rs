//! The one serializer of CSV cells: a row (a struct) into its field names and cells, each
//! float written as [`super::num`] does, `None` as an empty cell.

use super::num;
use serde::ser::{self, Impossible, Serialize, SerializeMap, SerializeStruct, Serializer};
use std::fmt;

/// The field names and cells of a row.
pub(super) fn cells<R: Serialize>(row: &R) -> Result<(Vec<String>, Vec<String>), CellError> {
    let mut out = RowCells::default();
    row.serialize(&mut out)?;
    Ok((out.names, out.cells))
}

/// Why a row could not be written: it is not a struct of plain cells.
#[derive(Debug)]
pub(super) struct CellError(pub(super) String);

impl fmt::Display for CellError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for CellError {}

impl ser::Error for CellError {
    fn custom<T: fmt::Display>(msg: T) -> Self {
        CellError(msg.to_string())
    }
}

impl From<csv::Error> for CellError {
    fn from(e: csv::Error) -> Self {
        CellError(e.to_string())
    }
}

/// The methods of a [`Serializer`] that refuse every scalar with `refuse()`.
macro_rules! refuse_scalars {
    ($ok:ty, $refuse:ident) => {
        refuse_scalars!(@each $ok, $refuse; serialize_bool: bool, serialize_i8: i8,
            serialize_i16: i16, serialize_i32: i32, serialize_i64: i64, serialize_u8: u8,
            serialize_u16: u16, serialize_u32: u32, serialize_u64: u64, serialize_f32: f32,
            serialize_f64: f64, serialize_char: char, serialize_str: &str);
    };
    (@each $ok:ty, $refuse:ident; $($method:ident: $t:ty),*) => {
        $(
            fn $method(self, _: $t) -> Result<$ok, CellError> {
                $refuse()
            }
        )*
    };
}

/// The methods of a [`Serializer`] that refuse sequences and tuples with `refuse()`.
macro_rules! refuse_sequences {
    ($refuse:ident) => {
        fn serialize_seq(self, _: Option<usize>) -> Result<Self::SerializeSeq, CellError> {
            $refuse()
        }
        fn serialize_tuple(self, _: usize) -> Result<Self::SerializeTuple, CellError> {
            $refuse()
        }
        fn serialize_tuple_struct(
            self,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeTupleStruct, CellError> {
            $refuse()
        }
        fn serialize_tuple_variant(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: usize,
        ) -> Result<Self::SerializeTupleVariant, CellError> {
            $refuse()
        }
    };
}

/// The methods of the cell [`Serializer`] that write a value as its `Display` does.
macro_rules! as_text {
    ($($method:ident: $t:ty),*) => {
        $(
            fn $method(self, v: $t) -> Result<String, CellError> {
                Ok(v.to_string())
            }
        )*
    };
}

/// A row being serialised: a struct, its fields the cells (a struct with flattened parts
/// comes as a map of its fields).
#[derive(Default)]
struct RowCells {
    names: Vec<String>,
    cells: Vec<String>,
}

impl SerializeStruct for &mut RowCells {
    type Ok = ();
    type Error = CellError;

    fn serialize_field<T: ?Sized + Serialize>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), CellError> {
        self.names.push(key.to_string());
        self.cells.push(value.serialize(Cell)?);
        Ok(())
    }

    fn end(self) -> Result<(), CellError> {
        Ok(())
    }
}

impl SerializeMap for &mut RowCells {
    type Ok = ();
    type Error = CellError;

    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> Result<(), CellError> {
        self.names.push(key.serialize(Cell)?);
        Ok(())
    }

    fn serialize_value<T: ?Sized + Serialize>(&mut self, value: &T) -> Result<(), CellError> {
        self.cells.push(value.serialize(Cell)?);
        Ok(())
    }

    fn end(self) -> Result<(), CellError> {
        Ok(())
    }
}

/// Refuses anything but a struct as a row.
fn not_a_row<T>() -> Result<T, CellError> {
    Err(CellError("a CSV row is a struct of plain cells".into()))
}

impl Serializer for &mut RowCells {
    type Ok = ();
    type Error = CellError;
    type SerializeSeq = Impossible<(), CellError>;
    type SerializeTuple = Impossible<(), CellError>;
    type SerializeTupleStruct = Impossible<(), CellError>;
    type SerializeTupleVariant = Impossible<(), CellError>;
    type SerializeMap = Self;
    type SerializeStruct = Self;
    type SerializeStructVariant = Impossible<(), CellError>;

    fn serialize_struct(self, _: &'static str, _: usize) -> Result<Self, CellError> {
        Ok(self)
    }
    refuse_scalars!((), not_a_row);

    fn serialize_bytes(self, _: &[u8]) -> Result<(), CellError> {
        not_a_row()
    }
    fn serialize_none(self) -> Result<(), CellError> {
        not_a_row()
    }
    fn serialize_some<T: ?Sized + Serialize>(self, _: &T) -> Result<(), CellError> {
        not_a_row()
    }
    fn serialize_unit(self) -> Result<(), CellError> {
        not_a_row()
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<(), CellError> {
        not_a_row()
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
    ) -> Result<(), CellError> {
        not_a_row()
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: &T,
    ) -> Result<(), CellError> {
        not_a_row()
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: &T,
    ) -> Result<(), CellError> {
        not_a_row()
    }
    refuse_sequences!(not_a_row);
    fn serialize_map(self, _: Option<usize>) -> Result<Self, CellError> {
        Ok(self)
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeStructVariant, CellError> {
        not_a_row()
    }
}

/// The one serializer of a cell: a float as [`num`], an integer or text as it is, `None` as
/// an empty cell, a unit variant by its name.
struct Cell;

/// Refuses a nested value as a cell.
fn not_a_cell<T>() -> Result<T, CellError> {
    Err(CellError(
        "a CSV cell is a number, a text or nothing".into(),
    ))
}

impl Serializer for Cell {
    type Ok = String;
    type Error = CellError;
    type SerializeSeq = Impossible<String, CellError>;
    type SerializeTuple = Impossible<String, CellError>;
    type SerializeTupleStruct = Impossible<String, CellError>;
    type SerializeTupleVariant = Impossible<String, CellError>;
    type SerializeMap = Impossible<String, CellError>;
    type SerializeStruct = Impossible<String, CellError>;
    type SerializeStructVariant = Impossible<String, CellError>;

    fn serialize_f64(self, v: f64) -> Result<String, CellError> {
        Ok(num(v))
    }
    fn serialize_f32(self, v: f32) -> Result<String, CellError> {
        Ok(num(f64::from(v)))
    }
    as_text!(serialize_bool: bool, serialize_i8: i8, serialize_i16: i16, serialize_i32: i32,
        serialize_i64: i64, serialize_u8: u8, serialize_u16: u16, serialize_u32: u32,
        serialize_u64: u64, serialize_char: char, serialize_str: &str);

    fn serialize_bytes(self, _: &[u8]) -> Result<String, CellError> {
        not_a_cell()
    }
    fn serialize_none(self) -> Result<String, CellError> {
        Ok(String::new())
    }
    fn serialize_some<T: ?Sized + Serialize>(self, v: &T) -> Result<String, CellError> {
        v.serialize(self)
    }
    fn serialize_unit(self) -> Result<String, CellError> {
        Ok(String::new())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Result<String, CellError> {
        Ok(String::new())
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
    ) -> Result<String, CellError> {
        Ok(variant.to_string())
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        v: &T,
    ) -> Result<String, CellError> {
        v.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: &T,
    ) -> Result<String, CellError> {
        not_a_cell()
    }
    refuse_sequences!(not_a_cell);
    fn serialize_map(self, _: Option<usize>) -> Result<Self::SerializeMap, CellError> {
        not_a_cell()
    }
    fn serialize_struct(
        self,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeStruct, CellError> {
        not_a_cell()
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Self::SerializeStructVariant, CellError> {
        not_a_cell()
    }
}
