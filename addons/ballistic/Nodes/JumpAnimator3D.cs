#nullable enable
using System;
using Ballistic.Runtime.Agents;
using Ballistic.Runtime.Core;
using Ballistic.Runtime.Hosting;
using Ballistic.Runtime.Skeletons;
using Godot;
using NumericsQuaternion = System.Numerics.Quaternion;
using NumericsVector3 = System.Numerics.Vector3;

namespace Ballistic.Addon;

/// <summary>
/// The procedural animation player: every frame it poses a <see cref="Skeleton3D"/> from the runtime's whole-body
/// animation of a <see cref="JumpAgent3D"/> at its path time (contact poses by IK, takeoff and landing phases, flight,
/// the walking gait), matching the
/// rig's joints to the skeleton's bones by name (<see cref="SkeletonBinding"/>: Godot's name sanitising, optional
/// renames, different rests, helper nodes between bones). It can also bake the agent's planned path into an
/// <see cref="Animation"/> in an <see cref="AnimationLibrary"/> so designers can scrub it in the animation editor.
/// </summary>
[GlobalClass]
[Icon("res://addons/ballistic/icons/JumpAnimator3D.svg")]
public partial class JumpAnimator3D : Node
{
    private SkeletonBinding? _binding;
    private Skeleton3D? _skeleton;
    private JumpAgent3D? _agent;
    private NumericsQuaternion[] _rotations = [];
    private NumericsVector3[] _positions = [];
    private string _bindError = "";

    /// <summary>The agent whose pose is played; empty: a <see cref="JumpAgent3D"/> beside this node.</summary>
    [Export]
    public NodePath AgentPath { get; set; } = new();

    /// <summary>The skeleton to drive; empty: the first <see cref="Skeleton3D"/> under this node's parent.</summary>
    [Export]
    public NodePath SkeletonPath { get; set; } = new();

    /// <summary>Rig joint name → skeleton bone name, for bones whose names differ.</summary>
    [Export]
    public Godot.Collections.Dictionary<string, string> BoneRenames { get; set; } = [];

    /// <summary>Drive the skeleton every frame (off: leave it to an <see cref="AnimationPlayer"/>).</summary>
    [Export]
    public bool Active { get; set; } = true;

    /// <summary>Why the skeleton could not be bound to the character's rig; empty when bound.</summary>
    public string GetBindError() => _bindError;

    /// <summary>Finds the agent and skeleton and binds the rig's joints to the bones.</summary>
    public override void _Ready()
    {
        if (Engine.IsEditorHint())
        {
            return;
        }

        _agent = AgentPath.IsEmpty
            ? GetParent()?.FindChildren("*", "", recursive: false, owned: false).OfType<JumpAgent3D>().FirstOrDefault()
            : GetNodeOrNull<JumpAgent3D>(AgentPath);
        _skeleton = SkeletonPath.IsEmpty
            ? GetParent()?.FindChildren("*", nameof(Skeleton3D), recursive: true, owned: false).OfType<Skeleton3D>().FirstOrDefault()
            : GetNodeOrNull<Skeleton3D>(SkeletonPath);
        if (_agent is null || _skeleton is null)
        {
            Fail(_agent is null ? "no JumpAgent3D found (set AgentPath)" : "no Skeleton3D found (set SkeletonPath)");
            return;
        }

        JumpCharacter? character = _agent.GetRoadmap()?.Character;
        if (character is null)
        {
            Fail("the agent's JumpRoadmap3D has no Character");
            return;
        }

        int count = _skeleton.GetBoneCount();
        var names = new string[count];
        var parents = new int[count];
        var rests = new BoneTransform[count];
        for (int i = 0; i < count; i++)
        {
            names[i] = _skeleton.GetBoneName(i);
            parents[i] = _skeleton.GetBoneParent(i);
            Transform3D rest = _skeleton.GetBoneRest(i);
            rests[i] = new BoneTransform(rest.Origin.ToNumerics(), rest.Basis.GetRotationQuaternion().ToNumerics(), rest.Basis.Scale.ToNumerics());
        }

        try
        {
            var renames = BoneRenames.ToDictionary(pair => pair.Key, pair => pair.Value);
            SkeletonBindingResult bound = SkeletonBinding.Create(character.Load().Model, new TargetSkeleton(names, parents, rests), new SkeletonBindingOptions { Renames = renames });
            if (bound.Binding is null)
            {
                Fail(bound.Error ?? "the skeleton does not match the rig");
                return;
            }

            _binding = bound.Binding;
        }
        catch (Exception e) when (e is Planner.IO.BallisticInputException or ArgumentException)
        {
            Fail(e.Message);
            return;
        }

        _rotations = new NumericsQuaternion[count];
        _positions = new NumericsVector3[count];
    }

    /// <summary>Poses the skeleton from the agent's current whole-body pose.</summary>
    public override void _Process(double delta)
    {
        if (!Active || _binding is null || _skeleton is null || _agent?.Logic is not JumpAgentLogic logic
            || logic.Lifecycle != AgentLifecycle.Active)
        {
            return;
        }

        RuntimeResult converted = _binding.Convert(logic.World, logic.Agent, SkeletonGlobal(_skeleton), _rotations, _positions);
        if (!converted.Ok)
        {
            return;
        }

        foreach (int bone in _binding.DrivenBones)
        {
            _skeleton.SetBonePoseRotation(bone, _rotations[bone].ToGodot());
        }

        foreach (int bone in _binding.PositionedBones)
        {
            _skeleton.SetBonePosePosition(bone, _positions[bone].ToGodot());
        }
    }

    /// <summary>
    /// Bakes the agent's current path (from its start, in world space as the skeleton stands now) into an animation
    /// named <paramref name="animationName"/> in the library <paramref name="libraryName"/> of
    /// <paramref name="player"/> (created when missing), at <paramref name="frameRate"/> frames per second.
    /// </summary>
    /// <returns><see cref="Error.Ok"/>, or <see cref="Error.Unavailable"/> when the agent has no path or the skeleton is not bound.</returns>
    public Error BakeAnimation(AnimationPlayer player, string libraryName = "ballistic", string animationName = "path", float frameRate = 30f)
    {
        ArgumentNullException.ThrowIfNull(player);
        if (_binding is null || _skeleton is null || _agent?.Logic?.CurrentPath is not { } path)
        {
            GD.PushWarning($"{Name}: nothing to bake ({(_binding is null ? _bindError : "the agent has no path")}).");
            return Error.Unavailable;
        }

        Node root = player.GetNodeOrNull(player.RootNode) ?? player.GetParent();
        var settings = new ClipBakeSettings { FrameRate = frameRate, SkeletonPath = root.GetPathTo(_skeleton).ToString() };
        BakedClip clip = AnimationClipBaker.Bake(path, _binding, SkeletonGlobal(_skeleton), settings);
        var animation = new Animation { Length = clip.Length, LoopMode = Animation.LoopModeEnum.None };
        foreach (BoneRotationTrack track in clip.RotationTracks)
        {
            int index = animation.AddTrack(Animation.TrackType.Rotation3D);
            animation.TrackSetPath(index, track.Path);
            for (int k = 0; k < track.Times.Length; k++)
            {
                animation.RotationTrackInsertKey(index, track.Times[k], track.Rotations[k].ToGodot());
            }
        }

        foreach (BonePositionTrack track in clip.PositionTracks)
        {
            int index = animation.AddTrack(Animation.TrackType.Position3D);
            animation.TrackSetPath(index, track.Path);
            for (int k = 0; k < track.Times.Length; k++)
            {
                animation.PositionTrackInsertKey(index, track.Times[k], track.Positions[k].ToGodot());
            }
        }

        AnimationLibrary library = player.HasAnimationLibrary(libraryName) ? player.GetAnimationLibrary(libraryName) : new AnimationLibrary();
        if (!player.HasAnimationLibrary(libraryName))
        {
            player.AddAnimationLibrary(libraryName, library);
        }

        if (library.HasAnimation(animationName))
        {
            library.RemoveAnimation(animationName);
        }

        return library.AddAnimation(animationName, animation);
    }

    private static BoneTransform SkeletonGlobal(Skeleton3D skeleton)
    {
        Transform3D t = skeleton.GlobalTransform;
        return new BoneTransform(t.Origin.ToNumerics(), t.Basis.GetRotationQuaternion().ToNumerics(), t.Basis.Scale.ToNumerics());
    }

    private void Fail(string reason)
    {
        _bindError = reason;
        GD.PushError($"{GetPath()}: {reason}");
    }
}
