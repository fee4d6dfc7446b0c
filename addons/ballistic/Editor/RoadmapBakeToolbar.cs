#nullable enable
#if TOOLS
using Godot;

namespace Ballistic.Addon.Editor;

/// <summary>
/// The 3D editor toolbar shown with a <see cref="JumpRoadmap3D"/> selected: "Bake Jump Roadmap" starts a threaded
/// bake with a progress dialog the user can cancel; "Clear" removes the baked data (undoable). A failed bake opens an
/// error dialog with the reason and keeps the previous data. The bake itself is the node's; this only shows it.
/// </summary>
[Tool]
public partial class RoadmapBakeToolbar : HBoxContainer
{
    private readonly Button _bake = new() { Text = "Bake Jump Roadmap", Flat = true, TooltipText = "Bake the selected JumpRoadmap3D's roadmap on a thread." };
    private readonly Button _clear = new() { Text = "Clear", Flat = true, TooltipText = "Remove the baked roadmap data." };
    private readonly ConfirmationDialog _progressDialog = new() { Title = "Baking Jump Roadmap", MinSize = new Vector2I(420, 0) };
    private readonly ProgressBar _progressBar = new() { MaxValue = 1.0, Step = 0.001, ShowPercentage = true, CustomMinimumSize = new Vector2(400, 0) };
    private readonly Label _progressText = new();
    private readonly AcceptDialog _errorDialog = new() { Title = "Jump roadmap bake failed" };
    private JumpRoadmap3D? _baking;

    /// <summary>The editor's undo history (set by the plugin from <c>EditorPlugin.GetUndoRedo()</c>).</summary>
    public EditorUndoRedoManager? UndoRedo { get; set; }

    /// <summary>The roadmap node the buttons act on (set by the plugin).</summary>
    public JumpRoadmap3D? Roadmap { get; set; }

    /// <summary>Builds the buttons and dialogs.</summary>
    public override void _Ready()
    {
        AddChild(_bake);
        AddChild(_clear);
        var box = new VBoxContainer();
        box.AddChild(_progressText);
        box.AddChild(_progressBar);
        _progressDialog.AddChild(box);
        _progressDialog.GetOkButton().Visible = false;
        _progressDialog.GetCancelButton().Text = "Cancel";
        _progressDialog.Canceled += OnCancel;
        AddChild(_progressDialog);
        AddChild(_errorDialog);
        _bake.Pressed += OnBake;
        _clear.Pressed += OnClear;
    }

    /// <summary>Refreshes the progress dialog while a bake runs and reports its end.</summary>
    public override void _Process(double delta)
    {
        if (_baking is null)
        {
            return;
        }

        if (!GodotObject.IsInstanceValid(_baking))
        {
            _baking = null;
            _progressDialog.Hide();
            return;
        }

        if (_baking.IsBaking())
        {
            _progressBar.Value = _baking.GetBakeProgress();
            _progressText.Text = _baking.GetBakeStatusText();
            return;
        }

        JumpRoadmap3D finished = _baking;
        _baking = null;
        _progressDialog.Hide();
        if (finished.GetLastBakeError() is { Length: > 0 } error)
        {
            _errorDialog.DialogText = error;
            _errorDialog.PopupCentered();
            return;
        }

        SaveBakedData(finished);
    }

    private void OnBake()
    {
        if (Roadmap is null || _baking is not null)
        {
            return;
        }

        // BakeRoadmap returns nothing: a bake that cannot start ends at once, not baking, with its reason.
        Roadmap.BakeRoadmap(onThread: true);
        if (!Roadmap.IsBaking() && Roadmap.GetLastBakeError() is { Length: > 0 } refused)
        {
            _errorDialog.DialogText = refused;
            _errorDialog.PopupCentered();
            return;
        }

        _baking = Roadmap;
        _progressBar.Value = 0;
        _progressText.Text = "Parsing source geometry…";
        _progressDialog.PopupCentered();
    }

    private void OnCancel() => _baking?.CancelBake();

    private void OnClear()
    {
        if (Roadmap is null || Roadmap.Roadmap is null || UndoRedo is not EditorUndoRedoManager undo)
        {
            return;
        }

        undo.CreateAction("Clear Jump Roadmap");
        undo.AddDoProperty(Roadmap, JumpRoadmap3D.PropertyName.Roadmap, default(Variant));
        undo.AddUndoProperty(Roadmap, JumpRoadmap3D.PropertyName.Roadmap, Roadmap.Roadmap);
        undo.CommitAction();
        Roadmap.UpdateGizmos();
    }

    /// <summary>
    /// Saves the new data as a binary resource beside the scene (like a baked NavigationMesh), or over the file it was
    /// loaded from, so that the scene stays small and the data survives reloads.
    /// </summary>
    private static void SaveBakedData(JumpRoadmap3D node)
    {
        if (node.Roadmap is not JumpRoadmapData data)
        {
            return;
        }

        string path = data.ResourcePath;
        if (string.IsNullOrEmpty(path) || path.Contains("::", System.StringComparison.Ordinal))
        {
            string scene = node.Owner?.SceneFilePath ?? node.SceneFilePath;
            string folder = string.IsNullOrEmpty(scene) ? "res://" : scene.GetBaseDir();
            string stem = string.IsNullOrEmpty(scene) ? "jump_roadmap" : scene.GetFile().GetBaseName();
            path = $"{folder}/{stem}_{node.Name}.res";
        }

        Error saved = ResourceSaver.Save(data, path, ResourceSaver.SaverFlags.ChangePath);
        if (saved != Error.Ok)
        {
            EditorInterface.Singleton.GetEditorToaster().PushToast($"Could not save the jump roadmap to {path}: {saved}.", EditorToaster.Severity.Error);
            return;
        }

        EditorInterface.Singleton.GetResourceFilesystem().UpdateFile(path);
        EditorInterface.Singleton.MarkSceneAsUnsaved();
        node.UpdateGizmos();
        EditorInterface.Singleton.GetEditorToaster().PushToast($"Jump roadmap baked: {data.NodeCount} stances, {data.JumpCount} jumps in {data.BakeSeconds:0.0} s ({path}).", EditorToaster.Severity.Info);
    }
}
#endif
