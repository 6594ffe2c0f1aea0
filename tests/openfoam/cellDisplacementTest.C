/*---------------------------------------------------------------------------*\
  dcpRBF tests: cellDisplacement, as the preCICE adapter uses it
-------------------------------------------------------------------------------
License
    This file is part of dcpRBF. Copyright (C) 2026 the dcpRBF authors.
    GPL-3.0-or-later: see the LICENSE file at the top of the repository.
-------------------------------------------------------------------------------
Description
    dcpRBF registers a volVectorField cellDisplacement as
    displacementLaplacian does. The preCICE OpenFOAM adapter's FSI module
    (locations faceCenters) writes a coupled patch's face displacements into
    its boundary, interpolates them to the patch's points into
    pointDisplacement and updates the mesh: the patch moves to those
    values, the mesh is valid, and cellDisplacement then holds the cells'
    and faces' averages of the point displacement. A 0/cellDisplacement is
    read with its own conditions: a fixedValue face keeps what the adapter
    wrote into it.

\*---------------------------------------------------------------------------*/

#include "cellByCellQuality.H"
#include "testHelpers.H"
#include "dcpRBFCellQuality.H"
#include "primitivePatchInterpolation.H"
#include "volFields.H"

#include <gtest/gtest.h>

using namespace Foam;
using namespace Foam::dcpRBFTest;

namespace
{

const std::string coeffs =
    "movingPatches (bottom); staticPatches (left right top);"
    " supportRadius 0.4; controlPoints { selection greedy; }";

//- What the adapter does before the mesh update: face values into
//  cellDisplacement's patch, interpolated to its points in pointDisplacement;
//  returns the points' values
vectorField adapterWrites(const fvMesh& mesh, const word& patchName, const vectorField& faces)
{
    const label patchi = mesh.boundaryMesh().findPatchID(patchName);
    volVectorField& cd = const_cast<volVectorField&>
    (
        mesh.lookupObject<volVectorField>("cellDisplacement")
    );
    cd.boundaryFieldRef()[patchi] == faces;
    const vectorField points
    (
        primitivePatchInterpolation(mesh.boundaryMesh()[patchi])
       .faceToPointInterpolate(cd.boundaryField()[patchi])
    );
    pointVectorField& pd = const_cast<pointVectorField&>
    (
        mesh.lookupObject<pointVectorField>("pointDisplacement")
    );
    refCast<vectorField>(pd.boundaryFieldRef()[patchi]) = points;
    return points;
}

//- The bottom's face values: a bump of its face centres
vectorField bump(const fvMesh& mesh)
{
    const label patchi = mesh.boundaryMesh().findPatchID("bottom");
    const vectorField cf(mesh.boundaryMesh()[patchi].faceCentres());
    vectorField v(cf.size());
    forAll(cf, i)
    {
        v[i] = vector(0, 0.04*Foam::sin(constant::mathematical::pi*cf[i].x()), 0);
    }
    return v;
}


TEST(CellDisplacement, AdapterFaceValuesMoveThePatchMeshValid)
{
    testCase c(2, 16, coeffs);
    autoPtr<motionSolver> ms(select(c));
    ASSERT_TRUE(c.mesh().foundObject<volVectorField>("cellDisplacement"));
    const volVectorField& cd = c.mesh().lookupObject<volVectorField>("cellDisplacement");
    const label bottom = c.mesh().boundaryMesh().findPatchID("bottom");
    EXPECT_EQ(cd.boundaryField()[bottom].type(), "cellMotion");
    ++c.runTime();
    const vectorField wanted(adapterWrites(c.mesh(), "bottom", bump(c.mesh())));
    const pointField p0(c.mesh().points());
    const pointField p(ms->newPoints());

    // the patch's points where the adapter put them
    const labelList& mp = c.mesh().boundaryMesh()[bottom].meshPoints();
    scalar err = 0;
    forAll(mp, i)
    {
        err = max(err, mag(p[mp[i]] - p0[mp[i]] - wanted[i]));
    }
    EXPECT_LT(err, 1e-15);
    const labelList cells(identity(c.mesh().nCells()));
    EXPECT_GT(gMin(cellByCellQuality(c.mesh(), cells, p0, p)), 0.5);

    // cellDisplacement: the cells' averages of their points' displacement,
    // the patch's faces' averages (cellMotion)
    const vectorField& d = refCast<dcpRBFMotionSolver>(ms()).pointDisplacement().primitiveField();
    scalar cellErr = 0;
    forAll(cells, celli)
    {
        vector sum(Zero);
        for (const label pointi : c.mesh().cellPoints()[celli]) sum += d[pointi];
        cellErr = max(cellErr, mag(cd[celli] - sum/scalar(c.mesh().cellPoints()[celli].size())));
    }
    EXPECT_LT(cellErr, 1e-15);
    scalar faceErr = 0;
    const polyPatch& pp = c.mesh().boundaryMesh()[bottom];
    forAll(pp, facei)
    {
        vector sum(Zero);
        for (const label pointi : pp[facei]) sum += d[pointi];
        faceErr = max(faceErr, mag(cd.boundaryField()[bottom][facei] - sum/scalar(pp[facei].size())));
    }
    EXPECT_LT(faceErr, 1e-12);
}


TEST(CellDisplacement, ReadWithItsConditionsFixedValueKeepsTheAdaptersValues)
{
    testCase c(2, 16, coeffs);
    c.write
    (
        "0/cellDisplacement", "volVectorField",
        "dimensions [0 1 0 0 0 0 0];\ninternalField uniform (0 0 0);\n"
        "boundaryField\n{\n"
        "    bottom { type fixedValue; value uniform (0 0 0); }\n"
        "    \"(left|right|top)\" { type cellMotion; value uniform (0 0 0); }\n"
        "    \"(front|back)\" { type empty; }\n}\n"
    );
    autoPtr<motionSolver> ms(select(c));
    const volVectorField& cd = c.mesh().lookupObject<volVectorField>("cellDisplacement");
    const label bottom = c.mesh().boundaryMesh().findPatchID("bottom");
    ASSERT_EQ(cd.boundaryField()[bottom].type(), "fixedValue");
    ++c.runTime();
    const vectorField faces(bump(c.mesh()));
    adapterWrites(c.mesh(), "bottom", faces);
    ms->newPoints();
    // not lost: what the adapter wrote is there after the step
    scalar err = 0;
    forAll(faces, i)
    {
        err = max(err, mag(cd.boundaryField()[bottom][i] - faces[i]));
    }
    EXPECT_EQ(err, 0);
}

TEST(CellDisplacement, ConstraintPatchWithAPointConditionOfItsOwn)
{
    // a constraint patch whose point condition no finite-volume field has
    // (oscillatingDisplacement on a symmetry plane, like
    // solidBodyMotionDisplacement on an overset patch): its own type
    testCase c(3, 4, coeffs, "symmetryPlane");
    c.write
    (
        "0/pointDisplacement", "pointVectorField",
        "dimensions [0 1 0 0 0 0 0];\ninternalField uniform (0 0 0);\n"
        "boundaryField\n{\n"
        "    \"(left|right|top|bottom)\" { type fixedValue; value uniform (0 0 0); }\n"
        "    \"(front|back)\" { patchType symmetryPlane; type oscillatingDisplacement;"
        " amplitude (0 0 0); omega 1; value uniform (0 0 0); }\n}\n"
    );
    autoPtr<motionSolver> ms(select(c));
    const volVectorField& cd = c.mesh().lookupObject<volVectorField>("cellDisplacement");
    const label front = c.mesh().boundaryMesh().findPatchID("front");
    EXPECT_EQ(cd.boundaryField()[front].type(), "symmetryPlane");
}

} // namespace

// ************************************************************************* //
