#include "dgwarpMotionSolver.H"

#include "addToRunTimeSelectionTable.H"
#include "emptyPolyPatch.H"
#include "labelIOList.H"
#include "processorCyclicPolyPatch.H"
#include "processorPolyPatch.H"
#include "pyramidPointFaceRef.H"
#include "solidBodyMotionDisplacementPointPatchVectorField.H"
#include "valuePointPatchField.H"
#include "wedgePolyPatch.H"

#include "motion_bridge.hpp"

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace Foam
{
    defineTypeNameAndDebug(dgwarpMotionSolver, 0);
    addToRunTimeSelectionTable(motionSolver, dgwarpMotionSolver, dictionary);
    addToRunTimeSelectionTable(displacementMotionSolver, dgwarpMotionSolver, displacement);
}

namespace
{

enum Role { fixedRole = 0, movingRole = 1, interfaceRole = 2 };

// Entries of dgwarpCoeffs that are the motion solver's, not the method's.
bool solverEntry(const Foam::word& key)
{
    return key == "method" || key == "repair" || key == "movingPatches" || key == "allowInverted" ||
        key == "rotations" || key == "invertedCells";
}

// The one value of a method option's entry, as text.
std::string entryText(const Foam::dictionary& coeffs, const Foam::entry& e)
{
    using namespace Foam;
    if (e.isDict())
    {
        FatalIOErrorInFunction(coeffs)
            << "dgwarpCoeffs: " << e.keyword() << " is a method option: it takes one value, not a dictionary"
            << exit(FatalIOError);
    }
    ITstream& is = e.stream();
    token t(is);
    std::string value;
    if (t.isWord()) value = t.wordToken();
    else if (t.isString()) value = t.stringToken();
    else if (t.isBool()) value = t.boolToken() ? "true" : "false";
    else if (t.isNumber())
    {
        char text[40];
        std::snprintf(text, sizeof text, "%.17g", double(t.number()));
        value = text;
    }
    if (value.empty() || !is.eof())
    {
        FatalIOErrorInFunction(coeffs)
            << "dgwarpCoeffs: " << e.keyword() << " takes one value (a number or a word), as the flag --"
            << e.keyword() << " of dgwarp deform" << exit(FatalIOError);
    }
    return value;
}

// Conditions whose points the motion solver holds fixed (without movingPatches).
bool fixedCondition(const Foam::word& type)
{
    return type == "slip" || type == "fixedNormalSlip" || type == "zeroGradient";
}

// The largest |value| of a patch's condition when it holds values (fixedValue and the
// conditions derived from it), over every processor; -1 when it holds none.
Foam::scalar conditionMagnitude(const Foam::pointPatchField<Foam::vector>& pf)
{
    using namespace Foam;
    const bool holds = isA<valuePointPatchField<vector>>(pf);
    if (!returnReduce(holds, orOp<bool>())) return -1;
    scalar largest = 0;
    if (holds)
    {
        const Field<vector>& v = refCast<const valuePointPatchField<vector>>(pf);
        if (v.size()) largest = max(mag(v));
    }
    return returnReduce(largest, maxOp<scalar>());
}

} // End anonymous namespace


Foam::dgwarpMotionSolver::dgwarpMotionSolver(const polyMesh& mesh, const IOdictionary& dict)
:
    displacementMotionSolver(mesh, dict, typeName)
{
    readCoeffs();
}


Foam::dgwarpMotionSolver::dgwarpMotionSolver
(
    const polyMesh& mesh,
    const IOdictionary& dict,
    const pointVectorField& pointDisplacement,
    const pointIOField& points0
)
:
    displacementMotionSolver(mesh, dict, pointDisplacement, points0, typeName)
{
    readCoeffs();
}


Foam::dgwarpMotionSolver::~dgwarpMotionSolver()
{}


void Foam::dgwarpMotionSolver::readCoeffs()
{
    // Checked now (a typo fails at the start, not at the first time step).
    const dictionary& coeffs = coeffDict();
    for (const entry& e : coeffs)
    {
        if (!solverEntry(e.keyword())) entryText(coeffs, e);
    }
}


void Foam::dgwarpMotionSolver::prepare()
{
    const dictionary& coeffs = coeffDict();
    dgwarp_bridge::Settings settings;
    settings.method = coeffs.lookupOrDefault<word>("method", "dg-harmonic");
    // No repair by default: a repair runs on one process only, and the points
    // must not depend on the number of processes.
    settings.repair = coeffs.lookupOrDefault<word>("repair", "none");
    const word criterion = coeffs.lookupOrDefault<word>("invertedCells", "pyramids");
    if (criterion != "pyramids" && criterion != "corners")
    {
        FatalIOErrorInFunction(coeffs)
            << "dgwarpCoeffs: invertedCells must be pyramids (checkMesh's criterion) or corners (Knupp's), got "
            << criterion << exit(FatalIOError);
    }
    for (const entry& e : coeffs)
    {
        if (!solverEntry(e.keyword())) settings.options.emplace_back(e.keyword(), entryText(coeffs, e));
    }
    // dg-harmonic's guard off unless asked for: its redo (the laplacian reference on the
    // whole mesh) needs the cells, which a parallel run's plan does not have, and takes
    // seconds to minutes, too long for a time step.
    if (settings.method == "dg-harmonic" && !coeffs.found("harmonic-redo-below"))
    {
        settings.options.emplace_back("harmonic-redo-below", "-1");
    }
    const bool listed = coeffs.found("movingPatches");
    const wordRes movingNames(listed ? coeffs.get<wordRes>("movingPatches") : wordRes());

    // What each patch does.
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    roles_.setSize(patches.size());
    DynamicList<word> moving, fixed;
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        const pointPatchField<vector>& pf = pointDisplacement_.boundaryField()[patchi];
        if (isA<processorCyclicPolyPatch>(pp)) roles_[patchi] = fixedRole;
        else if (isA<processorPolyPatch>(pp)) roles_[patchi] = interfaceRole;
        else if (isA<emptyPolyPatch>(pp) || isA<wedgePolyPatch>(pp))
        {
            FatalErrorInFunction
                << "dgwarp: patch " << pp.name() << " is of type " << pp.type()
                << ": 2D and axisymmetric cases need their points to slide in the patch's plane, which the dgwarp"
                << " motion solver does not do yet (use displacementLaplacian for such cases)" << exit(FatalError);
        }
        else if (listed) roles_[patchi] = movingNames.match(pp.name()) ? movingRole : fixedRole;
        else if (polyPatch::constraintType(pp.type()) || fixedCondition(pf.type())) roles_[patchi] = fixedRole;
        else if (pf.type() == "fixedValue") roles_[patchi] = conditionMagnitude(pf) > 0 ? movingRole : fixedRole;
        else roles_[patchi] = movingRole;
        if (roles_[patchi] == movingRole) moving.append(pp.name());
        else if (roles_[patchi] == fixedRole) fixed.append(pp.name());
    }
    if (listed)
    {
        for (const wordRe& name : movingNames)
        {
            bool found = false;
            forAll(patches, patchi) found = found || (roles_[patchi] == movingRole && name.match(patches[patchi].name()));
            if (!found)
            {
                FatalIOErrorInFunction(coeffs)
                    << "dgwarpCoeffs: movingPatches names " << name << ", which is no patch of the mesh; the patches are "
                    << patches.names() << exit(FatalIOError);
            }
        }
    }

    // Each patch's bounding-box centre (the same on every processor).
    rotations_ = coeffs.lookupOrDefault<bool>("rotations", true);
    centres_.setSize(patches.size());
    forAll(patches, patchi)
    {
        const pointField pts(points0(), patches[patchi].meshPoints());
        centres_[patchi] = 0.5*(gMin(pts) + gMax(pts));
    }

    // The mesh at points0, as plain arrays.
    dgwarp_bridge::PolyMesh m;
    const pointField& p0 = points0();
    m.points.reserve(3*p0.size());
    for (const point& p : p0)
    {
        m.points.push_back(p.x());
        m.points.push_back(p.y());
        m.points.push_back(p.z());
    }
    const faceList& faces = mesh().faces();
    m.face_offsets.reserve(faces.size() + 1);
    m.face_offsets.push_back(0);
    for (const face& f : faces)
    {
        m.face_nodes.insert(m.face_nodes.end(), f.begin(), f.end());
        m.face_offsets.push_back(m.face_nodes.size());
    }
    m.owner.assign(mesh().faceOwner().begin(), mesh().faceOwner().end());
    m.neighbour.assign(mesh().faceNeighbour().begin(), mesh().faceNeighbour().end());
    m.num_cells = mesh().nCells();
    forAll(patches, patchi)
    {
        const polyPatch& pp = patches[patchi];
        dgwarp_bridge::Patch p;
        p.name = pp.name();
        p.type = pp.type();
        p.start = pp.start();
        p.size = pp.size();
        p.role =
            roles_[patchi] == movingRole ? dgwarp_bridge::PatchRole::moving
          : roles_[patchi] == fixedRole ? dgwarp_bridge::PatchRole::fixed
          : dgwarp_bridge::PatchRole::interface;
        m.patches.push_back(p);
    }

    // A parallel run: every point's number in the whole mesh.
    std::unique_ptr<dgwarp_bridge::Parallel> parallel;
    if (Pstream::parRun())
    {
        labelIOList addressing
        (
            IOobject
            (
                "pointProcAddressing",
                mesh().facesInstance(),
                polyMesh::meshSubDir,
                mesh(),
                IOobject::READ_IF_PRESENT,
                IOobject::NO_WRITE,
                false
            )
        );
        const bool ok = addressing.size() == mesh().nPoints();
        if (!returnReduce(ok, andOp<bool>()))
        {
            FatalErrorInFunction
                << "dgwarp: a parallel run needs each processor's constant/polyMesh/pointProcAddressing"
                << " (written by decomposePar) with one label per point; "
                << (ok ? "another processor" : "this processor") << " has " << addressing.size() << " for "
                << mesh().nPoints() << " points" << exit(FatalError);
        }
        parallel.reset(new dgwarp_bridge::Parallel);
        parallel->global_ids.assign(addressing.begin(), addressing.end());
    }

    Info<< "dgwarp: moving patches " << moving << ", fixed patches " << fixed << endl;
    try
    {
        solver_.reset(new dgwarp_bridge::Solver(std::move(m), settings, parallel.get()));
    }
    catch (const dgwarp_bridge::Error& e)
    {
        FatalErrorInFunction << "dgwarp: " << e.what() << exit(FatalError);
    }
    Info<< solver_->summary().c_str() << (Pstream::parRun() ? " (processor 0)" : "") << endl;
}


std::vector<dgwarp_bridge::RigidMotion> Foam::dgwarpMotionSolver::rigidMotions() const
{
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    std::vector<dgwarp_bridge::RigidMotion> out(patches.size());
    if (!rotations_) return out;
    forAll(patches, patchi)
    {
        const pointPatchField<vector>& pf = pointDisplacement_.boundaryField()[patchi];
        if (roles_[patchi] != movingRole || !isA<solidBodyMotionDisplacementPointPatchVectorField>(pf)) continue;
        // x' = R(x - s) (septernion::transformPoint) = c + R(x - c) + t with t = R(c - s) - c.
        const septernion tr =
            refCast<const solidBodyMotionDisplacementPointPatchVectorField>(pf).motion().transformation();
        quaternion q = tr.r();
        if (q.w() < 0) q = quaternion(-q.w(), -q.v());  // the same rotation, by the smaller angle
        const scalar s = mag(q.v());
        const vector w = s > 0 ? (2*atan2(s, q.w())/s)*q.v() : vector::zero;
        const vector& c = centres_[patchi];
        const vector t = q.transform(c - tr.t()) - c;
        dgwarp_bridge::RigidMotion& m = out[patchi];
        m.rigid = true;
        for (direction k = 0; k < 3; ++k)
        {
            m.rotation[k] = w[k];
            m.centre[k] = c[k];
            m.translation[k] = t[k];
        }
    }
    return out;
}


Foam::labelList Foam::dgwarpMotionSolver::invalidCells(const pointField& points) const
{
    const faceList& faces = mesh().faces();
    const labelList& own = mesh().faceOwner();
    const labelList& nei = mesh().faceNeighbour();
    const label nCells = mesh().nCells();

    // Face centres and areas, then cell centres and volumes, as fvMesh
    // (primitiveMesh::makeCellCentresAndVols).
    vectorField fCtrs(faces.size()), fAreas(faces.size());
    forAll(faces, facei)
    {
        fCtrs[facei] = faces[facei].centre(points);
        fAreas[facei] = faces[facei].areaNormal(points);
    }
    vectorField cEst(nCells, Zero);
    labelList nCellFaces(nCells, 0);
    forAll(own, facei)
    {
        cEst[own[facei]] += fCtrs[facei];
        ++nCellFaces[own[facei]];
    }
    forAll(nei, facei)
    {
        cEst[nei[facei]] += fCtrs[facei];
        ++nCellFaces[nei[facei]];
    }
    forAll(cEst, celli) cEst[celli] /= nCellFaces[celli];
    vectorField cellCtrs(nCells, Zero);
    scalarField cellVols(nCells, 0);
    forAll(own, facei)
    {
        const scalar pyr3Vol = fAreas[facei] & (fCtrs[facei] - cEst[own[facei]]);
        cellCtrs[own[facei]] += pyr3Vol*((3.0/4.0)*fCtrs[facei] + (1.0/4.0)*cEst[own[facei]]);
        cellVols[own[facei]] += pyr3Vol;
    }
    forAll(nei, facei)
    {
        const scalar pyr3Vol = fAreas[facei] & (cEst[nei[facei]] - fCtrs[facei]);
        cellCtrs[nei[facei]] += pyr3Vol*((3.0/4.0)*fCtrs[facei] + (1.0/4.0)*cEst[nei[facei]]);
        cellVols[nei[facei]] += pyr3Vol;
    }
    forAll(cellCtrs, celli)
    {
        cellCtrs[celli] = mag(cellVols[celli]) > VSMALL ? cellCtrs[celli]/cellVols[celli] : cEst[celli];
    }
    cellVols /= 3.0;

    // checkFacePyramids and checkCellVolumes.
    boolList bad(nCells, false);
    forAll(cellVols, celli) bad[celli] = cellVols[celli] < VSMALL;
    forAll(faces, facei)
    {
        if (-pyramidPointFaceRef(faces[facei], cellCtrs[own[facei]]).mag(points) < -SMALL) bad[own[facei]] = true;
        if (facei < nei.size() && pyramidPointFaceRef(faces[facei], cellCtrs[nei[facei]]).mag(points) < -SMALL)
        {
            bad[nei[facei]] = true;
        }
    }
    DynamicList<label> out;
    forAll(bad, celli) if (bad[celli]) out.append(celli);
    return labelList(std::move(out));
}


void Foam::dgwarpMotionSolver::checkFixedPatches() const
{
    const polyBoundaryMesh& patches = mesh().boundaryMesh();
    forAll(patches, patchi)
    {
        if (roles_[patchi] != fixedRole || polyPatch::constraintType(patches[patchi].type())) continue;
        const scalar d = conditionMagnitude(pointDisplacement_.boundaryField()[patchi]);
        if (d > 0)
        {
            FatalErrorInFunction
                << "dgwarp: patch " << patches[patchi].name() << " is held fixed (its pointDisplacement was zero"
                << " when the motion solver was prepared, or movingPatches does not name it), but its condition"
                << " now moves it by up to " << d << ": name it in dgwarpCoeffs' movingPatches" << exit(FatalError);
        }
    }
}


Foam::tmp<Foam::pointField> Foam::dgwarpMotionSolver::curPoints() const
{
    if (newPoints_.size() == mesh().nPoints())
    {
        return tmp<pointField>(new pointField(newPoints_));
    }
    return points0() + pointDisplacement_.primitiveField();
}


void Foam::dgwarpMotionSolver::solve()
{
    movePoints(mesh().points());
    pointDisplacement_.boundaryFieldRef().updateCoeffs();
    pointDisplacement_.correctBoundaryConditions();
    if (!solver_) prepare();
    checkFixedPatches();

    const vectorField& d = pointDisplacement_.primitiveField();
    const label n = d.size();
    std::vector<double> displacement(3*n), out(3*n);
    forAll(d, i)
    {
        displacement[3*i] = d[i].x();
        displacement[3*i + 1] = d[i].y();
        displacement[3*i + 2] = d[i].z();
    }
    dgwarp_bridge::StepResult r;
    try
    {
        r = solver_->step(displacement.data(), rigidMotions(), out.data());
    }
    catch (const dgwarp_bridge::Error& e)
    {
        FatalErrorInFunction << "dgwarp: " << e.what() << exit(FatalError);
    }
    newPoints_.setSize(n);
    forAll(newPoints_, i)
    {
        newPoints_[i] = point(out[3*i], out[3*i + 1], out[3*i + 2]);
    }
    // The whole field's displacement, as displacementLaplacian leaves it; the
    // conditions' own values again at the patches' points (not new - points0,
    // which may differ from them in the last bit).
    pointDisplacement_.primitiveFieldRef() = newPoints_ - points0();
    pointDisplacement_.correctBoundaryConditions();

    for (const std::string& w : r.warnings) Warning<< "dgwarp: " << w.c_str() << endl;
    const label cells = returnReduce(label(r.cells), sumOp<label>());
    const label inverted = returnReduce(label(r.inverted), sumOp<label>());
    const label repaired = returnReduce(label(r.repaired), sumOp<label>());
    const bool redo = returnReduce(r.guard_redo, orOp<bool>());
    const scalar minQuality = returnReduce(r.min_quality, minOp<scalar>());
    const scalar meanQuality = returnReduce(r.mean_quality*r.cells, sumOp<scalar>())/max(cells, label(1));
    const scalar stepSeconds = returnReduce(r.step_seconds, maxOp<scalar>());
    const scalar qualitySeconds = returnReduce(r.quality_seconds, maxOp<scalar>());
    Info<< "dgwarp: step " << stepSeconds << " s, measure " << qualitySeconds << " s, quality min " << minQuality
        << " mean " << meanQuality;
    if (redo) Info<< ", dg-harmonic's guard kept the laplacian reference's result";
    if (repaired) Info<< ", " << (r.last_resort ? "last resort" : "untangling") << " mended " << repaired << " cells";
    Info<< ", " << inverted << " of " << cells << " cells inverted" << endl;

    if (inverted > 0)
    {
        // Cells with a folded corner (Knupp's quality <= 0): does OpenFOAM refuse them too?
        const labelList refused(r.inverted > 0 ? invalidCells(newPoints_) : labelList());
        const label nRefused = returnReduce(refused.size(), sumOp<label>());
        const bool corners = coeffDict().lookupOrDefault<word>("invertedCells", "pyramids") == "corners";
        if (r.inverted > 0)
        {
            std::ostringstream cellsText;
            for (const auto c : r.worst_inverted) cellsText << " " << c;
            Pout<< "dgwarp: " << label(r.inverted) << " cells with a folded corner here, the worst:"
                << cellsText.str().c_str();
            if (refused.size())
            {
                Pout<< "; " << refused.size() << " with a negative face pyramid or volume:";
                for (label i = 0; i < min(refused.size(), label(10)); ++i) Pout<< " " << refused[i];
            }
            Pout<< endl;
        }
        const label bad = corners ? inverted : nRefused;
        const word what = corners ? "folds a corner of" : "inverts (negative face pyramids or volumes)";
        if (bad == 0)
        {
            WarningInFunction << "dgwarp: the motion at time " << time().timeName() << " folds a corner of "
                << inverted << " cells (Knupp's quality <= 0), whose face pyramids are all positive: OpenFOAM's"
                << " checkMesh accepts them; going on (invertedCells corners: an error)" << endl;
        }
        else if (coeffDict().lookupOrDefault<bool>("allowInverted", false))
        {
            WarningInFunction << "dgwarp: the motion at time " << time().timeName() << " " << what << " " << bad
                << " cells (allowInverted: going on)" << endl;
        }
        else
        {
            FatalErrorInFunction
                << "dgwarp: the motion at time " << time().timeName() << " " << what << " " << bad << " of the "
                << cells << " cells (listed above, the worst first); smaller time steps or motions, another method,"
                << " or allowInverted true in dgwarpCoeffs to go on" << exit(FatalError);
        }
    }
}


void Foam::dgwarpMotionSolver::updateMesh(const mapPolyMesh& mpm)
{
    displacementMotionSolver::updateMesh(mpm);
    solver_.reset();  // prepared again at the next solve
    newPoints_.clear();
}
