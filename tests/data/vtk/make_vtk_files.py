#!/usr/bin/env python3
"""Writes the VTK test files of tests/data/vtk from meshes/patch.off with two
writers that are not ours: VTK's own (vtkPolyDataWriter, legacy versions 4.2
and 5.1, ASCII and binary, with point and cell attributes and field data,
and triangle strips from vtkStripper; and vtkXMLPolyDataWriter's .vtp in every
data mode, compressed or not, with 32- and 64-bit headers) and meshio's. Run once with a Python
that has `vtk` and `meshio` (pip install vtk meshio); the files are committed,
and the tests read them back against the same mesh read from OFF:

    python3 tests/data/vtk/make_vtk_files.py   # VTK 9.7.2, meshio 5.3.5 wrote the committed files
"""
import pathlib

import meshio
import numpy as np
import vtk

HERE = pathlib.Path(__file__).resolve().parent
SOURCE = HERE.parents[2] / "meshes" / "patch.off"


def read_off(path):
    words = path.read_text().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    at = 4
    points = np.array(words[at:at + 3 * nv], dtype=float).reshape(nv, 3)
    at += 3 * nv
    faces = []
    for _ in range(nf):
        k = int(words[at])
        faces.append([int(w) for w in words[at + 1:at + 1 + k]])
        at += 1 + k
    return points, np.array(faces)


def polydata(points, faces):
    data = vtk.vtkPolyData()
    vtk_points = vtk.vtkPoints()
    vtk_points.SetDataTypeToDouble()
    for p in points:
        vtk_points.InsertNextPoint(*p)
    cells = vtk.vtkCellArray()
    for f in faces:
        cells.InsertNextCell(len(f), [int(i) for i in f])
    data.SetPoints(vtk_points)
    data.SetPolys(cells)
    # Attributes and field data a segmentation tool might leave in the file.
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputData(data)
    normals.SplittingOff()
    normals.ConsistencyOff()
    normals.Update()
    out = normals.GetOutput()
    labels = vtk.vtkIntArray()
    labels.SetName("label")
    for c in range(out.GetNumberOfCells()):
        labels.InsertNextValue(c % 3)
    out.GetCellData().AddArray(labels)
    note = vtk.vtkDoubleArray()
    note.SetName("scale")
    note.InsertNextValue(1.5)
    out.GetFieldData().AddArray(note)
    return out


def write_legacy(data, name, binary, version):
    writer = vtk.vtkPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(str(HERE / name))
    writer.SetFileVersion(version)
    if binary:
        writer.SetFileTypeToBinary()
    else:
        writer.SetFileTypeToASCII()
    assert writer.Write() == 1


def write_xml(data, name, mode, compressed, header64, block_size=4096):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(str(HERE / name))
    if mode == "ascii":
        writer.SetDataModeToAscii()
    elif mode == "binary":
        writer.SetDataModeToBinary()
    else:
        writer.SetDataModeToAppended()
        writer.SetEncodeAppendedData(mode == "appended_base64")
    if compressed:
        writer.SetCompressorTypeToZLib()
        writer.SetBlockSize(block_size)  # 4096: several blocks per array
    else:
        writer.SetCompressorTypeToNone()
    writer.SetHeaderTypeToUInt64() if header64 else writer.SetHeaderTypeToUInt32()
    assert writer.Write() == 1


def write_tetrahedron_files():
    """A small mesh as VTK writes it by default (issue 50). The compressed
    .vtp has one block per array, each smaller than VTK's default block size
    of 32768 bytes; the binary legacy files hold a FIELD array of strings
    whose lengths take 1, 2 and 4 bytes (5, 70 and 16,400 characters), one
    string empty and one with a line break."""
    points = np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], dtype=float)
    data = polydata(points, [(0, 2, 1), (0, 1, 3), (1, 2, 3), (0, 3, 2)])
    write_xml(data, "tetrahedron_zlib_one_small_block.vtp", "binary", True, False, block_size=32768)
    names = vtk.vtkStringArray()
    names.SetName("names")
    for text in ["alpha", "", "two words", "v" * 70, "new\nline", "w" * 16400]:
        names.InsertNextValue(text)
    data.GetFieldData().AddArray(names)
    for version in (42, 51):
        write_legacy(data, f"tetrahedron_strings_vtk{version}_binary.vtk", True, version)


def main():
    points, faces = read_off(SOURCE)
    data = polydata(points, faces)
    for version in (42, 51):
        for binary in (False, True):
            write_legacy(data, f"patch_vtk{version}_{'binary' if binary else 'ascii'}.vtk", binary, version)
    stripper = vtk.vtkStripper()
    stripper.SetInputData(data)
    stripper.Update()
    strips = stripper.GetOutput()
    assert strips.GetNumberOfStrips() > 0
    write_legacy(strips, "patch_strips_vtk51_binary.vtk", True, 51)
    write_legacy(strips, "patch_strips_vtk42_ascii.vtk", False, 42)
    for name, mode, compressed, header64 in [
        ("ascii", "ascii", False, False),
        ("binary", "binary", False, False),
        ("binary_zlib", "binary", True, False),
        ("appended_raw", "appended_raw", False, True),
        ("appended_raw_zlib", "appended_raw", True, False),
        ("appended_base64_zlib", "appended_base64", True, True),
    ]:
        write_xml(data, f"patch_{name}.vtp", mode, compressed, header64)
    write_xml(strips, "patch_strips_appended_raw.vtp", "appended_raw", False, False)
    write_tetrahedron_files()
    mesh = meshio.Mesh(points, [("triangle", faces)])
    meshio.write(HERE / "patch_meshio_binary.vtk", mesh, file_format="vtk", binary=True)
    meshio.write(HERE / "patch_meshio_ascii.vtk", mesh, file_format="vtk", binary=False)


if __name__ == "__main__":
    main()
